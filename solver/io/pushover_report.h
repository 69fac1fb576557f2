// Output of `isopound pushover`: pushover.csv (the capacity-curve table, one row per step, SI)
// and pushover.json (what was pushed and how, and the first-yield and capping points: their row
// in pushover.csv, roof displacement and base shear), read by `isopound-post pushover`.
#pragma once

#include <string>

#include "solver/structures/pushover_curve.h"

namespace isopound {

void write_pushover_csv(const std::string& path, const BuildingPushoverResult& result);

// `model_file` as given on the command line. Keys: model_file, building, dimension, pattern,
// angle_deg (3D; 0 in 2D), target_drift_ratio, height_m, steps, columns, first_yield and capping
// ({row, roof_displacement_m, roof_drift_ratio, base_shear_N} or null).
void write_pushover_json(const std::string& path, const std::string& model_file,
                         const BuildingPushoverOptions& options,
                         const BuildingPushoverResult& result);

}  // namespace isopound
