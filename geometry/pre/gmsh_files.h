// Gmsh output of isopound-pre (the only code that includes gmsh.h): one model per floor level and
// one of the whole site, as .geo_unrolled and .msh, with physical groups "structure/level/role";
// and area integrals of a slab over a Gmsh triangle mesh (the check of the polygon formulas).
#pragma once

#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "solver/structures/site_plan.h"

namespace isopound::pre {

// Initialises Gmsh (quiet) for the lifetime of the object; one at a time per process.
class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

struct GmshFile {
  std::string stem;                 // "site", "level-z3.20m"
  double elevation = -1.0;          // m; < 0 for the whole site
  std::vector<std::string> groups;  // physical group names
};

// Writes DIR/<stem>.geo_unrolled and DIR/<stem>.msh for every level and the site. Roles: slab
// (plane surface), column (the oriented rectangle b x h, on the level it stands on), bearing
// (point), wall (plane surface; the walls around a building's base slab are the group
// "<building>/base/wall", one surface per side, at z = 0). Entities sit at z = their elevation;
// fixed-base buildings' storey-1 columns are "<building>/ground/column" at z = 0. Needs a
// GmshSession.
std::vector<GmshFile> write_gmsh_files(const Site& site, const std::string& dir);

// Area, centroid and polar moment about the centroid of a convex polygon integrated over a Gmsh
// triangle mesh (element size `size`, m) with Gmsh's Gauss points and Jacobians; `triangles`
// receives the element count. Needs a GmshSession.
AreaProperties mesh_area_properties(const std::vector<Vec2>& plan, double size, int& triangles);

}  // namespace isopound::pre
