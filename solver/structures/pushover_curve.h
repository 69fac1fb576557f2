// The capacity curve of `isopound pushover` (2D: pushover2d.h, 3D: pushover3d.h): the command's
// options, the table written to pushover.csv and the two marked points of the curve.
// Conventions: roof_displacement_m is the roof's displacement along the push (2D: x; 3D: its
// centre of mass along the angle), base_shear_N the sum of the lateral loads along the push
// (static equilibrium: the shear at the foundation, through the isolators when there are any).
#pragma once

#include <string>
#include <vector>

namespace isopound {

struct BuildingPushoverOptions {
  enum class Pattern { kFirstMode, kUniform };
  Pattern pattern = Pattern::kFirstMode;
  double target_drift_ratio = 0.02;  // roof displacement / building height
  int steps = 200;
  double angle = 0.0;  // rad from the plan's x axis, counter-clockwise (3D only)
};

struct BuildingPushoverResult {
  std::string building;
  int dimension = 2;    // 2 or 3
  double height = 0.0;  // m, the building's height above its foundation (storeys)
  // Columns: roof_displacement_m, roof_drift_ratio, base_shear_N first; then per storey.
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int first_yield_row = -1;  // first row where a yielding storey / column reaches its yield drift
  int capping_row = -1;      // row of the largest base shear if the curve falls after it (or -1)
};

const char* pattern_name(BuildingPushoverOptions::Pattern pattern);

// Sets capping_row from the base_shear_N column (index 2): the row of its largest magnitude,
// when a later row is smaller by more than 1e-9 relative (a falling branch follows).
void mark_capping_point(BuildingPushoverResult& result);

}  // namespace isopound
