// Peaks a study keeps per run, addressed by selectors "<where>.<quantity>" over the main building
// (structure 0) and all elements. Values are SI peaks of |x| over time; a group gives its maximum.
//
// 2D building:
//   base | roof | floor<N> | floors | levels  .  displacement | velocity | absolute_acceleration |
//       residual_displacement (|u| at the end; base.residual_displacement: the isolators')
//       (floors: max over floors 1..N; levels: also the base slab)
//   story<N> | stories  .  drift | drift_ratio | shear (N; story1.shear = base of the
//       superstructure) | residual_drift | residual_drift_ratio (|drift| at the end) |
//       ductility | hysteretic_energy (J; peak over time) (these two: yielding storeys only)
// 3D building (`structures:`; a plan point or column set may follow the level or story):
//   <level>[.cm | .corners | .corner<K> | .points]  .  displacement | absolute_acceleration
//       (resultant sqrt(x^2 + y^2) at each instant) | displacement_x | displacement_y |
//       absolute_acceleration_x | absolute_acceleration_y | residual_displacement (resultant at
//       the end); the point defaults to cm (centre of mass); corners: max over the plan's
//       vertices; corner<K>: vertex K (1-based, plan order); points: cm and corners
//   <level>  .  u | v | theta  (the diaphragm's DOFs at the plan origin; theta in rad)
//   <story>[.corners | .<column pattern>]  .  drift | drift_x | drift_y | drift_ratio (each
//       column's drift, resultant / x / y, ratio = resultant / storey height); without a column
//       set: the envelope over every column; corners: the grid's corner columns (A1, D1, A4, D4)
//       | residual_drift_ratio (the largest column's at the end) | shear (storey shear
//       resultant, N; recorded with yielding columns or p_delta) | ductility (max over the
//       yielding columns) | yielded (number of yielded columns) | hysteretic_energy (J, summed)
//   columns  .  the same over every storey (columns.yielded: yielded columns of the building)
// Everywhere:
//   energy  .  input | kinetic | elastic | viscous | hysteretic | error | relative_error |
//       max_relative_error
//   ground  .  pga | pgv | pgd
//   <element>  .  <output>   element label after its last '/' or the full label, '*' and '?'
//       wildcards ("isolator.force", "wall*.impacts", "bearing*.deformation",
//       "base|wall east.normal_force"); max over the matches, or their sum with the prefix "sum:"
//       ("sum:wall*.impacts"). A case without such elements (walls removed in a variant) gets an
//       empty cell; a selector that matches in no case is an error.
//   contacts  .  <output>   every 3D polygon contact pair (slab-wall, slab-slab): normal_force,
//       tangential_force, area, indentation, impacts, impact_velocity, time_in_stick,
//       time_in_slip, friction_dissipated_energy, impact_dissipated_energy, and
//       first_impact_time (the earliest onset over the matched pairs; empty when none)
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/core/model.h"
#include "solver/excitation/ground_motion.h"

namespace isopound {

struct OutputSelector {
  enum class Kind { kLevel, kStory, kElement, kEnergy, kGround };
  Kind kind = Kind::kLevel;
  std::string where;     // "base", "floor3", "stories", an element pattern, "contacts", ...
  std::string point;     // 3D: "cm", "corners", "corner2", "points"; a column pattern; "" = none
  std::string quantity;  // "displacement", "drift_ratio", "force", "pga", ...
  bool sum = false;      // elements: sum over the matches instead of the maximum
  std::string text;      // as written
};

// Checks the grammar above. Throws std::invalid_argument naming the problem.
OutputSelector parse_output_selector(std::string_view text);

// The SI unit of a selector's value ("m", "m/s2", "N", "J", "-" for ratios and counts).
std::string output_unit(const OutputSelector& selector);

// A selector bound to the DOFs, stories or element outputs of one model.
struct ResolvedOutput {
  OutputSelector::Kind kind = OutputSelector::Kind::kLevel;
  int quantity = 0;                  // which peak family / energy term / ground peak
  std::vector<int> indices;          // DOFs, stories or elements
  std::vector<int> element_outputs;  // per element in `indices`: its output index
  bool sum = false;
  // A 3D building's plan points and columns: `indices` are Model::probes; the peak taken is
  // x (0), y (1), resultant (2) or ratio (3). With at_end, the resultant at the end instead,
  // from the probes' terms (kept here) and the final displacement.
  int probe_component = -1;
  bool at_end = false;
  bool end_ratio = false;  // at_end: the resultant over the probe's length (a drift ratio)
  // first_impact_time: `element_outputs` are the in_contact outputs; the earliest time any of
  // them became 1 (NaN when none did).
  bool first_time = false;
  std::vector<PlanProbe> end_probes;
  // 2D yielding storeys (ductility, hysteretic_energy): per story in `indices`, its StoryLink's
  // element index and yield drift d_y (m).
  std::vector<int> story_links;
  std::vector<double> yield_drifts;
};

// Throws std::invalid_argument when the model has no such level, story, element or output.
ResolvedOutput resolve_output(const OutputSelector& selector, const Model& model);

// What a run must record (RunOptions::record) for evaluate_output to give these outputs the
// values it gives from a run that records everything.
RecordScope record_scope_of(const std::vector<ResolvedOutput>& outputs);

// `first_impact_times`: per element, the time of its first counted impact or -1 (the run's
// contact log, ContactEventLog, as summary.json's first_impact_time_s); without it,
// first_impact_time is the first accepted step in contact (one step after the located onset).
double evaluate_output(const ResolvedOutput& output, const AnalysisResult& result,
                       const GroundMotionPeaks& ground,
                       const std::vector<double>* first_impact_times = nullptr);

}  // namespace isopound
