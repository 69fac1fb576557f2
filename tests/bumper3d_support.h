// Test helpers shared by the 3D bumper tests (bumper3d_test.cpp, bumper3d_outline_test.cpp): the
// thesis building, alone or beside a fixed-base 2-storey neighbour 4 cm east of it, a run under
// the built-in pulse, and the x peaks of a run.
#pragma once

#include <string>
#include <vector>

#include "peak_comparison.h"
#include "solver/core/analysis.h"
#include "solver/excitation/ground_motion.h"
#include "solver/structures/job.h"
#include "tests/wall_run_support.h"

namespace isopound::test {

// The thesis building (3 storeys, 3 x 3 bays of 5.5 m, Bouc-Wen bearings, no damping) as the
// first item of `structures:`; `plan` its plan map (empty: the default), `extra` keys added to it
// (indented 4).
inline std::string thesis_building(const std::string& plan, const std::string& extra) {
  return R"(structures:
  - name: building
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
)" + (plan.empty() ? std::string() : "    plan: " + plan + "\n") +
         R"(    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    base: {mass: 340 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
    damping: {type: none}
)" + extra;
}

// That building and a fixed-base 2-storey neighbour 4 cm east of it: `building_plan`,
// `neighbour_plan` their plans (every level's: a YAML plan map); `building_extra` /
// `neighbour_extra` keys added to each (indented 4). The neighbour is placed by `adjacent`,
// centred on the building's bounding box.
inline std::string building_beside_neighbour(
    const std::string& building_plan, const std::string& building_extra,
    const std::string& neighbour_extra,
    const std::string& neighbour_plan = "{rectangle: [16.85 m, 16.85 m]}") {
  return thesis_building(building_plan, building_extra) +
         R"(  - name: neighbour
    isolated: false
    adjacent: {to: building, side: east, gap: 4 cm}
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    plan: )" +
         neighbour_plan +
         R"(
    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 2, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    damping: {type: none}
)" + neighbour_extra;
}

using BumperOutcome = Outcome;  // the model and its run (wall_run_support.h)

// The model run to t_end (s) under `motion`, no histories.
inline BumperOutcome run_bumper_model(const ModelConfig& c, const GroundMotion& motion,
                                      double t_end) {
  RunOptions o;
  o.output.histories = false;
  o.analysis.t_end = t_end;
  BumperOutcome r{build_model(c), {}};
  r.result = run_analysis(r.model, motion, o);
  return r;
}

// Displacement and absolute-acceleration peaks of every x DOF (head-on runs: y and θ stay at
// round-off, their peaks are noise).
inline std::vector<NamedPeak> x_peaks(const BumperOutcome& o) {
  std::vector<NamedPeak> p;
  for (std::size_t i = 0; i < o.model.dofs.size(); ++i)
    if (o.model.dofs[i].label.ends_with("(x)")) {
      p.push_back({"u " + o.model.dofs[i].label, o.result.displacement[i].value});
      p.push_back({"a " + o.model.dofs[i].label, o.result.absolute_acceleration[i].value});
    }
  return p;
}

}  // namespace isopound::test
