// isopound-pre's checks on a model the reader accepted (issue 12 item 1): structures overlapping at
// rest, clearances measured per side (walls, neighbours) against the declared gaps, floors of
// pounding pairs at equal levels; warnings for storey stiffness jumps > 3x, very eccentric mass
// (EC8 4.2.3.2(6): e > 0.30 r) and bearings fewer than 3 or collinear.
#pragma once

#include <string>
#include <vector>

#include "geometry/pre/model_scan.h"
#include "geometry/pre/problems.h"
#include "geometry/pre/properties.h"
#include "geometry/pre/site_plan.h"

namespace isopound::pre {

// Limits of the checks (the warnings' thresholds; reach = how close two structures must be for
// their floors to be a pounding pair).
struct CheckLimits {
  double stiffness_jump = 3.0;       // adjacent storeys' K ratio
  double eccentricity_ratio = 0.30;  // e / r (EC8 4.2.3.2(6))
  double reach = 2.0;  // m: contact.search_distance (pairs farther apart at rest cannot meet)
  double level_tolerance = 0.01;  // m: contact.elevation_tolerance (floors this close meet)
  double gap_tolerance = 1e-3;    // m: measured vs declared gap
};

// A clearance measured at rest between two bodies at one level (slab-slab or wall-slab).
struct Clearance {
  std::string a, b;  // "building/base", "wall east" / "east-neighbour/floor 1"
  int structure_a = -1, structure_b = -1;  // indices (a wall: the building it surrounds)
  std::string side;                        // side of a on which b lies: east, west, north, south
  double measured = 0.0;                   // m (< 0: overlap depth)
  double declared = -1.0;                  // m, < 0 when nothing was declared
  double elevation = 0.0;
  bool same_level = true;  // false: the nearest approach of two structures with no common level
  Vec2 p_WA, p_WB;         // the closest points (for dimensioning the plan)
};

// 3D models.
std::vector<Clearance> check_site(const ScannedModel& model, const Site& site,
                                  const std::vector<StructureProperties>& properties,
                                  const CheckLimits& limits, ProblemList& problems);
// 2D models: stiffness jumps, neighbour floors at equal levels.
void check_model2d(const ScannedModel& model, const CheckLimits& limits, ProblemList& problems);

// The side of A on which B lies, from the direction A -> B: "east" (+x), "west", "north", "south".
std::string side_name(Vec2 n_AB);
// Closest points of two disjoint convex polygons (brute force over vertex-edge pairs).
void closest_points(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Vec2& p_a, Vec2& p_b);

}  // namespace isopound::pre
