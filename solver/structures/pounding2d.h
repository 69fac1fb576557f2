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

// What a level at elevation z faces of building b (its levels at z_b, level_elevations plus its
// ground level `ground`), with a tolerance of 1 mm: a level of b (slab to slab, `level` its
// index), storey `floor` (1-based) strictly between its floors (its columns), the gap between
// floor k and a slab isolated above it, b's ground or foundation below it, or nothing (above
// its roof).
struct FacedPart {
  enum class Kind { kNothing, kLevel, kStorey, kIsolationGap, kBelowGround };
  Kind kind = Kind::kNothing;
  int level = -1;                       // kLevel: index into z_b
  int floor = 0;                        // kStorey: the floor above the storey (1-based)
  double z_lower = 0.0, z_upper = 0.0;  // kStorey: the storey's floors, m
};
FacedPart faced_part(const BuildingConfig& b, const std::vector<double>& z_b, double ground,
                     double z);

// Whether level index `level` is the building's isolated slab.
bool is_base_level(const BuildingConfig& building, int level);

}  // namespace isopound
