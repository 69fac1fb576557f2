// `isopound pushover` for a 3D building: the model's first building alone (walls, neighbours and
// the other buildings left out) pushed statically along an angle a in plan by the generic
// displacement-controlled pushover (solver/core/pushover.h).
//   control   the roof's centre of mass along a: c^T q = cos a (u - y_cm theta) +
//             sin a (v + x_cm theta) of the roof diaphragm (DOFs at the plan origin);
//   pattern   first_mode: M Phi_c Phi_c^T M iota_a, the dominant mode along a (with its
//             equal-frequency partners, dominant_mode_pattern); uniform: M iota_a;
//             iota_a = iota_x cos a + iota_y sin a (the diaphragms' rigid-body motion).
// Storey shears are the loads above each storey (static equilibrium), in x, y and along a; the
// base shear is the sum of all loads. A storey's drift is its upper floor's centre of mass
// relative to the floor (or ground) below at the same plan point, along a. First yield: the first
// row where a yielding column's drift, in its section axes and normalised by its yield drifts,
// reaches the unit circle (the coupled laws' yield surface).
#pragma once

#include "solver/structures/config.h"
#include "solver/structures/pushover_curve.h"

namespace isopound {

// Columns after the first three: base_shear_x_N, base_shear_y_N, then per storey
// story<k>_drift_m, story<k>_drift_ratio, story<k>_shear_N (along a), story<k>_shear_x_N,
// story<k>_shear_y_N. Throws std::invalid_argument for a 2D model and std::runtime_error if a
// step fails.
BuildingPushoverResult run_pushover3d(const ModelConfig& config,
                                      const BuildingPushoverOptions& options);

}  // namespace isopound
