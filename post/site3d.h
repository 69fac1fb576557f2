// The plan geometry of a 3D model at rest, as post-processing draws it: every slab and wall as a
// convex polygon in the model's plan frame W, the columns between levels and the bearings.
// A plan point p of a body with DOFs (u, v, θ) at the plan origin moves by (u − p_y θ, v + p_x θ).
#pragma once

#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "geometry/plan_shape.h"
#include "solver/structures/config.h"

namespace isopound::post {

// A slab (floor or base), a wall, or a rubber bumper's strip at rest.
struct PlanBody {
  std::string structure;     // "building", "east-neighbour", "wall east"; a strip: its key
  std::string level;         // "base", "floor 1", ..., "wall", "rubber"
  std::string role;          // "slab" | "wall" | "rubber"
  double elevation = 0.0;    // m: a slab's level (levels3d.h); a wall's or strip's top
  double height = 0.0;       // m: a wall's height, a strip's rubber height; a slab 0
  std::vector<Vec2> plan_W;  // outline, counter-clockwise (validated; L, T, U shapes allowed)
  Vec2 p_WCM;                // centre of mass at rest (slabs; walls and strips: centroid)
  std::string dof_label;     // history label of its DOFs ("building/floor 1"), "" when fixed
  // A rubber strip (issue 27, bumper_layer3d.h): the body it is glued to, whose motion it
  // shares; -1 for slabs and walls.
  int follows = -1;
  // Its separation at rest from the first structure's slabs (the nearest of them), shared by every
  // body of its structure; zero for the first structure's own bodies and strips' structures.
  // animation3d draws gaps scaled by it (gap_offset, animation.h).
  Vec2 gap_W;
  // The name contact labels use: "<structure>/<level>" for slabs, "<structure>" for walls and
  // strips ("wall east bumper", "east-neighbour/floor 1 west bumper bottomed").
  std::string key() const { return role == "slab" ? structure + "/" + level : structure; }
  // The outline's convex hull (the outline itself when convex), and the outline of any shape.
  ConvexPolygon polygon() const { return convex_hull(plan_W); }
  SimplePolygon outline() const { return SimplePolygon(plan_W); }
  bool convex() const { return is_convex_list(plan_W); }
};

// A column a slab strikes between its floors (issue 26, struck_columns3d.h).
struct PlanStruck {
  std::string label;         // the element's ("<striker>/<level> on <struck> story <k> column <C>")
  double node_height = 0.0;  // m, the struck node above the storey's lower floor
  int striker = -1;          // body index of the striking slab
  std::vector<Vec2> section_W;  // the column's section at rest (its contact polygon)
  // History columns of the node's drift from the chord between the floors (read_run; -1: none).
  int drift_x = -1, drift_y = -1;
};

// A column of a storey: from the level below (a body, or the ground) to the floor above.
struct PlanColumn {
  std::string label;  // "building/story 1/A1"
  Vec2 p_W;
  int lower = -1;       // body index, -1: the ground (a fixed-base building's first storey)
  int upper = -1;       // body index
  double height = 0.0;  // m, the storey height
  PlanStruck struck;    // struck.label empty: not struck
};

// A bearing under the base slab.
struct PlanBearing {
  std::string label;  // "building/bearing A1" (the history label of its outputs)
  Vec2 p_W;
  int base = -1;   // body index of the base slab
  int lower = -1;  // body index of the floor it stands on (isolated above a storey), -1: ground
};

struct Site3D {
  // Slabs of every structure (bottom to top), then walls, then rubber strips.
  std::vector<PlanBody> bodies;
  std::vector<PlanColumn> columns;
  std::vector<PlanBearing> bearings;
  int find(const std::string& key) const;  // body index by key(), -1 when absent
  // The struck column whose element is labelled `label`, or nullptr.
  const PlanColumn* struck(const std::string& label) const;
};

// Slabs, columns and bearings of every 3D structure of the model, its moat walls (from the
// solver's site_bodies(), whose slabs are checked against these) and the rubber strips of
// bumpered walls and slab faces, named as the solver's contact labels name them (pounding3d.h),
// and the columns the solver's struck-column elements act on (struck_columns3d.h).
// Throws std::invalid_argument for a non-convex plan (the solver would not have run).
Site3D site_geometry(const ModelConfig& config);

}  // namespace isopound::post
