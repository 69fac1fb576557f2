// Capping point and names of the capacity curve (pushover_curve.h).
#include "solver/structures/pushover_curve.h"

#include <cmath>

namespace isopound {

const char* pattern_name(BuildingPushoverOptions::Pattern pattern) {
  return pattern == BuildingPushoverOptions::Pattern::kUniform ? "uniform" : "first_mode";
}

void mark_capping_point(BuildingPushoverResult& r) {
  double peak_shear = 0.0;
  int peak_row = 0;
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    if (std::abs(r.rows[i][2]) > peak_shear) {
      peak_shear = std::abs(r.rows[i][2]);
      peak_row = static_cast<int>(i);
    }
  r.capping_row = -1;
  if (peak_row + 1 < static_cast<int>(r.rows.size()) &&
      std::abs(r.rows.back()[2]) < peak_shear * (1 - 1e-9))
    r.capping_row = peak_row;
}

}  // namespace isopound
