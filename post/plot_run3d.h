// The figures of a 3D run: time histories (base-slab displacement x, y and resultant at its
// centre of mass, the worst corner drift ratio of each storey, absolute accelerations, contact
// forces F_N and F_T per pair), bearing hysteresis per direction and the bearing orbit, and the
// base slab's trajectory in plan (centre of mass and corners) with the wall lines.
#pragma once

#include <vector>

#include "post/plot_run.h"
#include "post/run_data.h"

namespace isopound::post {

// time_histories.png, hysteresis.png (when the run has bearings), contacts.png (when the event
// log has pairs: F_N against δ_N and F_T against F_N per pair, one line per episode) and
// trajectory.png.
std::vector<NamedFigure> run_figures3d(const RunData& run);

// The worst corner of a storey: the corner of the upper floor's plan whose drift ratio peaks
// highest (|relative displacement of the corner| / storey height), and its history.
struct CornerDrift {
  std::string label;          // "building/story 2 corner 3"
  std::vector<double> ratio;  // per history row, -
  double peak = 0.0;
};
std::vector<CornerDrift> corner_drifts(const RunData& run);

}  // namespace isopound::post
