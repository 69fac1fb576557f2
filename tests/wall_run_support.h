// Test helpers for 3D models struck by the built-in pulse (the moat-wall tests): the thesis
// building in its walls, the pulse along a direction in plan, a run to a given time keeping the
// model (its elements' episodes), and a contact by its label.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "solver/core/analysis.h"
#include "solver/elements/polygon_contact.h"
#include "solver/excitation/ground_motion.h"
#include "solver/io/model_input.h"
#include "solver/structures/job.h"

namespace isopound::test {

// The thesis building (3 storeys, 3 x 3 bays of 5.5 m, configs/3d-xy5.yaml) with `base` and
// `walls` as given (YAML flow maps).
inline std::string moat_building(const std::string& base, const std::string& walls) {
  return R"(structures:
  - name: building
    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}
    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}
    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}
    bearing: {model: bouc_wen, Tb: 2.0 s, QW: 5 %, uy: 1 cm}
    damping: {type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4], bearing_stiffness: post_yield}
    base: )" +
         base + "\n    walls: " + walls + "\n";
}

// The built-in pulse along the direction at `angle` (rad) from x (peak ground velocity 1 m/s).
inline GroundMotion pulse_at(double angle) {
  GroundMotion g = make_pulse(PulseParameters{});
  g.acceleration_y = g.acceleration;
  for (std::size_t k = 0; k < g.acceleration.size(); ++k) {
    g.acceleration_y[k] *= std::sin(angle);
    g.acceleration[k] *= std::cos(angle);
  }
  return g;
}

struct Outcome {
  Model model;
  AnalysisResult result;
};

inline Outcome run_until(const ModelConfig& c, const GroundMotion& motion, double t_end) {
  RunOptions o = run_options(c);
  o.analysis.t_end = t_end;
  Outcome r{build_model(c), {}};
  r.result = run_analysis(r.model, motion, o);
  return r;
}

// The 3D contact labelled `label`, or nullptr.
inline const PolygonContact* polygon_contact(const Model& m, const std::string& label) {
  for (const auto& e : m.elements)
    if (e->label() == label) return dynamic_cast<const PolygonContact*>(e.get());
  return nullptr;
}

// Every 3D contact of the model that had an episode is passive in each: its largest net work on
// the structures over one is <= 1e-9 of that episode's gross work (the round-off of the gross
// work bounds what "passive" can resolve). Returns how many contacts had an episode.
inline int expect_every_episode_passive(const Model& m, const std::string& where = "") {
  int struck = 0;
  for (const auto& e : m.elements) {
    const auto* p = dynamic_cast<const PolygonContact*>(e.get());
    if (!p || p->episodes() == 0) continue;
    ++struck;
    EXPECT_LE(p->max_episode_net_work_relative(), 1e-9) << p->label() << where;
  }
  return struck;
}

}  // namespace isopound::test
