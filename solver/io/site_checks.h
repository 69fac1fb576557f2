// The site checks of a model at rest (issue 24 item 2): one implementation, run by the model
// reader (load_model: `isopound check`, `isopound run`) and by isopound-pre, so that a model
// passes all three or fails all three with the same messages. Every problem is collected (not
// only the first) and blames the key it concerns ("file:line:col: key: what").
//
// 3D: every column and bearing inside the slabs it joins; every centre of mass inside its slab;
// no two structures overlapping in plan at rest (slabs at any levels, columns over a common
// height, a column standing in another structure's slab); moat walls at their declared gap from
// the base slab, outside every other structure's slabs and columns; buildings placed by
// `adjacent` at the declared gap where their floors meet; floors of pounding pairs at equal
// levels (slab-to-column contact is outside the model). 2D: neighbours' floors at the levels of
// the building's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/io/problems.h"
#include "solver/io/yaml_reader.h"
#include "solver/structures/config.h"
#include "solver/structures/site_plan.h"

namespace isopound {

// Where each part of a 3D structure is written (nodes of the model file), for messages.
struct StructureMarks {
  std::optional<InputNode> item;      // the list item of `structures:`
  std::optional<InputNode> storeys;   // `storeys:` (short form or list)
  std::vector<InputNode> storey;      // per storey: its list item, or `storeys:` (short form)
  std::optional<InputNode> base;      // `base:`
  std::optional<InputNode> bearings;  // `bearings:` list
  std::optional<InputNode> walls;     // `walls:`
  std::optional<InputNode> adjacent;  // `adjacent:`
  // Per storey, per listed column: its `at` (empty for grid columns); per listed bearing: `at`.
  std::vector<std::vector<std::optional<InputNode>>> column_at;
  std::vector<std::optional<InputNode>> bearing_at;
};

// The marks of every item of `structures:` (a list; anything else gives none). Looks keys up
// only (no reads, no errors): the reader itself refuses what is malformed.
std::vector<StructureMarks> structure_marks(const InputNode& structures);

// Tolerances of the site checks.
struct SiteLimits {
  double reach = 2.0;  // m: contact.search_distance (pairs farther apart at rest cannot meet)
  double level_tolerance = 0.01;  // m: contact.elevation_tolerance (floors this close meet)
  double gap_tolerance = 1e-3;    // m: measured vs declared gap
};
SiteLimits site_limits(const ModelConfig& model);

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

// The 3D site checks; `marks` as structure_marks() gives them for `structures:`. Returns every
// clearance measured (isopound-pre prints and draws them).
std::vector<Clearance> check_site3d(const ModelConfig& model,
                                    const std::vector<StructureMarks>& marks, const Site& site,
                                    const SiteLimits& limits, ProblemList& problems);
// The 2D site checks; `neighbours` are the items of `neighbours:`.
void check_site2d(const ModelConfig& model, const std::vector<InputNode>& neighbours,
                  ProblemList& problems);

// The side of A on which B lies, from the direction A -> B: "east" (+x), "west", "north", "south".
std::string side_name(Vec2 n_AB);
// Closest points of two disjoint convex polygons (brute force over vertex-edge pairs).
void closest_points(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Vec2& p_a, Vec2& p_b);

}  // namespace isopound
