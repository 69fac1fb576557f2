// Assembly of a 2D shear building (THEORY section 1) into a Model: lumped masses, story
// springs, isolation element and dashpot, superstructure damping relative to the base slab.
#pragma once

#include <Eigen/Dense>

#include "solver/core/model.h"
#include "solver/structures/config.h"

namespace isopound {

// Adds the building's DOFs, matrices and elements to `model` (which may already hold other
// structures). Throws std::invalid_argument on an inconsistent building.
void add_building(Model& model, const BuildingConfig& building);

// The building's total mass, kg: the base slab (isolated) and every floor; the mass the
// isolator carries unless `carried_mass` is given.
double building_mass(const BuildingConfig& building);

Model make_model(const BuildingConfig& building);

// The fixed-base superstructure (floors only, story 1 to the ground): mass and stiffness.
struct ShearStick {
  Eigen::MatrixXd mass;
  Eigen::MatrixXd stiffness;
};
ShearStick fixed_base_superstructure(const BuildingConfig& building);

// Superstructure damping matrix C_s in coordinates relative to the base (Rayleigh at two
// fixed-base modes, or modal with the same ratio at every mode).
Eigen::MatrixXd superstructure_damping(const BuildingConfig& building);

}  // namespace isopound
