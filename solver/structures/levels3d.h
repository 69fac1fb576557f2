// The levels of a 3D building in elevation order (issue 27 item 2, docs/isolation-level.md): an
// isolated building with isolation_level k has floors 1..k (the fixed-base substructure), the
// isolated base slab, then floors k+1..n (the superstructure); k = 0 puts the base slab first.
// Storey s (1-based) joins floor s to the level under it: floor s - 1, the ground (s = 1), or
// the base slab (s = k + 1). The bearings join floor k (the ground when k = 0) to the base slab.
#pragma once

#include <string>
#include <vector>

#include "solver/structures/config3d.h"

namespace isopound {

struct Level3D {
  std::string name;                              // "base", "floor 1", ...
  const Diaphragm3DConfig* diaphragm = nullptr;  // in the building frame (points into the config)
  double elevation = 0.0;                        // m above the ground
  int floor = 0;                                 // 1..n, 0 for the base slab
};

// Every level, bottom to top (the index is the level's index in StructureInfo::level_dofs).
std::vector<Level3D> levels3d(const Building3DConfig& building);

// Level index of the isolated base slab (the isolation level k), -1 for a fixed-base building.
int base_level3d(const Building3DConfig& building);
// Level index of floor f (1..n).
int floor_level3d(const Building3DConfig& building, int floor);
// Level index under storey s (1..n): the floor or base slab it stands on, -1 for the ground.
int storey_lower_level3d(const Building3DConfig& building, int storey);
// Level index under the bearings (floor k), -1 for the ground (k = 0).
int bearing_lower_level3d(const Building3DConfig& building);
// Storeys whose columns stand on the ground (0-based storey index 0), or none.
bool storey_on_ground3d(const Building3DConfig& building, int storey);

// The fixed-base superstructure (storeys k + 1..n, fixed at the base slab) and the fixed-base
// substructure (storeys 1..k, no storey when k = 0) as buildings of their own, for damping and
// modes; a fixed-base building is its own superstructure.
Building3DConfig superstructure3d(const Building3DConfig& building);
Building3DConfig substructure3d(const Building3DConfig& building);

}  // namespace isopound
