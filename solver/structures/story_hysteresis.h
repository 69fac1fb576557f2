// The law of a yielding storey of a 2D shear building (FloorConfig::hysteresis): its yield point
// in the engineer's numbers, K_el = k the storey's elastic stiffness, F_y = k d_y, and the law of
// the drift from the hysteresis table (solver/materials/hysteresis_law.h: bilinear, bouc_wen,
// peak_oriented with its capping drift a fraction of the storey height).
#pragma once

#include <memory>

#include "solver/materials/hysteresis_law.h"
#include "solver/structures/config.h"

namespace isopound {

// Weight carried by storey `story` (0-based): g x the masses of the floors above it, N.
double weight_above_story(const BuildingConfig& b, int story);

// d_y of storey `story`, m, from yield_drift_ratio x height, yield_shear / k or
// yield_shear_coefficient x weight above / k.
double story_yield_drift(const BuildingConfig& b, int story);

// The storey's yield point: k, k d_y, d_y, alpha and the storey height.
YieldPoint story_yield_point(const BuildingConfig& b, int story);

// The storey's uniaxial law (its hysteresis must not be elastic).
std::unique_ptr<UniaxialMaterial> make_story_material(const BuildingConfig& b, int story);

}  // namespace isopound
