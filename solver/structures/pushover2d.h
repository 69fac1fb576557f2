// `isopound pushover` for a 2D building (the main building of a model, without walls and
// neighbours): the generic displacement-controlled pushover (solver/core/pushover.h) with the
// lateral pattern first_mode (M phi_1, default) or uniform (M iota), controlled by the roof
// displacement up to target_drift_ratio x the building's height. Storey shears are the loads
// above each storey (static equilibrium); the base shear is the sum of all loads.
// A 3D model's hook: the same run_pushover with control c = (cos a, sin a) on the roof centre
// and pattern M (iota_x cos a + iota_y sin a); not wired here (3D structures are refused).
#pragma once

#include <string>
#include <vector>

#include "solver/structures/config.h"

namespace isopound {

struct Pushover2DOptions {
  enum class Pattern { kFirstMode, kUniform };
  Pattern pattern = Pattern::kFirstMode;
  double target_drift_ratio = 0.02;  // roof displacement / building height
  int steps = 200;
};

struct Pushover2DResult {
  std::vector<std::string> columns;  // roof_displacement_m, roof_drift_ratio, base_shear_N, ...
  std::vector<std::vector<double>> rows;
  int first_yield_row = -1;  // first row where a yielding storey's |drift| >= d_y (or -1)
  int capping_row = -1;      // row of the largest base shear if it falls afterwards (or -1)
};

// Throws std::invalid_argument for a 3D model and std::runtime_error if a step fails.
Pushover2DResult run_pushover2d(const ModelConfig& config, const Pushover2DOptions& options);

void write_pushover_csv(const std::string& path, const Pushover2DResult& result);

}  // namespace isopound
