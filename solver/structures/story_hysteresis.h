// The law of a yielding storey of a 2D shear building (FloorConfig::hysteresis): its yield drift
// in the engineer's numbers and the uniaxial material of the drift, with k the storey's elastic
// stiffness and F_y = k d_y:
//   bilinear (kinematic hardening): F = alpha k d + F_h, |F_h| <= (1 - alpha) F_y;
//   bouc_wen: F = k (alpha d + (1 - alpha) d_y z),
//             dz/dt = (A dd/dt - gamma |dd/dt| |z|^(n-1) z - beta dd/dt |z|^n) / d_y;
//   peak_oriented: Ibarra-Medina-Krawinkler (solver/materials/peak_oriented.h).
#pragma once

#include <memory>

#include "solver/materials/hysteresis.h"
#include "solver/structures/config.h"

namespace isopound {

// Weight carried by storey `story` (0-based): g x the masses of the floors above it, N.
double weight_above_story(const BuildingConfig& b, int story);

// d_y of storey `story`, m, from yield_drift_ratio x height, yield_shear / k or
// yield_shear_coefficient x weight above / k.
double story_yield_drift(const BuildingConfig& b, int story);

// The storey's uniaxial law (its hysteresis must not be elastic).
std::unique_ptr<UniaxialMaterial> make_story_material(const BuildingConfig& b, int story);

const char* story_hysteresis_name(StoryHysteresisConfig::Model model);

}  // namespace isopound
