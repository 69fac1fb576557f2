// The site in plan as isopound-pre draws and meshes it: every slab (base slab and floors) of every
// 3D structure, its columns and bearings, and the walls, in the model's plan frame W (SI).
// Elevations and level order as levels3d.h: an isolated building's base slab at 0 (or
// isolation_height above floor isolation_level), floor f at the sum of the heights below it.
#pragma once

#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "solver/structures/config.h"

namespace isopound {

// A column drawn as the rectangle b x h (along its axes 1 and 2) with the column's I11 and I22
// (b h^3 / 12 and h b^3 / 12: exact for a rectangular section, an equivalent one otherwise).
struct PlanColumn {
  std::string label;
  Vec2 p_W;
  double b = 0.0, h = 0.0;              // m
  double orientation = 0.0;             // rad, axis 1 from x, plan frame
  std::vector<Vec2> outline_W() const;  // 4 corners, counter-clockwise
};

struct PlanBearing {
  std::string label;
  Vec2 p_W;
};

struct PlanSlab {
  int structure = 0;       // index in ModelConfig::structures3d
  std::string name;        // the structure's name
  std::string level;       // "base", "floor 1", ...
  int level_index = 0;     // 0 = the lowest slab of the structure
  double elevation = 0.0;  // m
  std::vector<Vec2> plan_W;
  double mass = 0.0;                  // kg
  Vec2 p_WM;                          // centre of mass
  std::vector<PlanColumn> columns;    // the columns standing on this slab (the storey above)
  std::vector<PlanBearing> bearings;  // base slab only (they stand on the level under it)
};

struct PlanWall {
  std::string name;           // "wall east"
  int building = 0;           // index of the building whose base slab it surrounds
  std::string structure;      // that building's name
  std::string side;           // "east", ...
  double declared_gap = 0.0;  // m, as written; < 0: none (walls along a polyline)
  double height = 0.0;
  double elevation = 0.0;  // m: its top, flush with the level it faces (the base slab's)
  std::vector<Vec2> plan_W;
  // A wall along a run of the slab's outline (walls: {follow: outline}): the unit normal from the
  // slab's face into the wall; its gap is the clearance along it (at a re-entrant corner whose
  // two walls have different gaps, the mitred end of the wider one comes nearer the other face).
  bool along_outline = false;
  Vec2 normal_W;
};

struct Site {
  std::vector<PlanSlab> slabs;
  // Storey-1 columns standing on the ground (z = 0): fixed-base buildings and substructures.
  std::vector<PlanColumn> ground_columns;
  std::vector<int> ground_columns_structure;
  std::vector<PlanWall> walls;
};

// Slabs, columns and bearings placed as building3d.cpp places them; walls from the solver's own
// site geometry (site_bodies(), solver/structures/pounding3d.h).
Site site_plan(const ModelConfig& config);

// Equivalent rectangle b x h of a column with I11 = b h^3 / 12 and I22 = h b^3 / 12.
void column_rectangle(double I11, double I22, double& b, double& h);

}  // namespace isopound
