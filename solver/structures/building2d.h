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

// The building's total mass, kg: the base slab (isolated) and every floor.
double building_mass(const BuildingConfig& building);
// The isolated part's mass, kg: the base slab and the floors above it (all floors for
// isolation_level 0); the mass the isolator carries unless `carried_mass` is given.
double isolated_mass(const BuildingConfig& building);

Model make_model(const BuildingConfig& building);

// The fixed-base superstructure (the floors above the isolated slab, their first story to the
// ground): mass and stiffness.
struct ShearStick {
  Eigen::MatrixXd mass;
  Eigen::MatrixXd stiffness;
};
ShearStick fixed_base_superstructure(const BuildingConfig& building);
// The fixed-base substructure: floors 1..isolation_level alone (0 x 0 for isolation_level 0).
ShearStick fixed_base_substructure(const BuildingConfig& building);

// Superstructure damping matrix C_s in coordinates relative to the base (Rayleigh at two
// fixed-base modes, or modal with the same ratio at every mode).
Eigen::MatrixXd superstructure_damping(const BuildingConfig& building);
// Substructure damping matrix, relative to the ground (building.substructure_damping).
Eigen::MatrixXd substructure_damping(const BuildingConfig& building);

}  // namespace isopound
