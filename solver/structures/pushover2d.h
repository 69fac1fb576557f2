// `isopound pushover` for a 2D building (the main building of a model, without walls and
// neighbours): the generic displacement-controlled pushover (solver/core/pushover.h) with the
// lateral pattern first_mode (M phi_1, default) or uniform (M iota), controlled by the roof
// displacement up to target_drift_ratio x the building's height. Storey shears are the loads
// above each storey (static equilibrium); the base shear is the sum of all loads.
// 3D buildings: pushover3d.h.
#pragma once

#include "solver/structures/config.h"
#include "solver/structures/pushover_curve.h"

namespace isopound {

// Throws std::invalid_argument for a 3D model (or an angle) and std::runtime_error if a step
// fails. Columns after the first three: story<k>_drift_m, story<k>_drift_ratio, story<k>_shear_N.
BuildingPushoverResult run_pushover2d(const ModelConfig& config,
                                      const BuildingPushoverOptions& options);

}  // namespace isopound
