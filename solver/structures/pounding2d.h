// Pounding set-ups in 2D: moat walls beside a level (rigid or a single-DOF structure) and
// neighbouring buildings pounding slab to slab at equal elevations, as Contact1D elements.
#pragma once

#include "solver/core/model.h"
#include "solver/structures/config.h"

namespace isopound {

// Adds the walls of structure `structure` (already in the model, built from `building`).
void add_walls(Model& model, int structure, const BuildingConfig& building,
               double steps_per_contact);

// Adds the neighbour as a new structure and its contacts with structure `main`.
void add_neighbour(Model& model, int main, const BuildingConfig& main_building,
                   const NeighbourConfig& neighbour, double steps_per_contact);

// Elevation of each level of a building in level order, m: floor i at the sum of the story
// heights below it, the isolated slab at 0 or, isolated above floor k, at z(floor k) +
// isolation_height (and the floors above it raised by that).
std::vector<double> level_elevations(const BuildingConfig& building);

// Whether level index `level` is the building's isolated slab.
bool is_base_level(const BuildingConfig& building, int level);

}  // namespace isopound
