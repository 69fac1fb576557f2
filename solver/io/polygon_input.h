// Polygons in plan read from YAML (convex ones, and plans of any simple outline): a list of [x, y] points whose coordinates may carry a
// length unit ("12 m", "350 cm"; a bare number is metres). Errors name file, line, key, vertex.
#pragma once

#include <string>
#include <vector>

#include "geometry/convex_polygon.h"
#include "geometry/simple_polygon.h"
#include "solver/io/yaml_reader.h"

namespace isopound {

// `node` is a list of at least 3 [x, y] points. An invalid polygon (ConvexPolygon's rules) is an
// InputError at the offending vertex ("pairs[0].b[2]: vertex 2 (1, 0): repeats vertex 1").
// Clockwise lists are accepted and reversed, as ConvexPolygon does.
ConvexPolygon read_polygon(const InputNode& node);
// The same list as a plan of any simple outline (SimplePolygon's rules: L, T and U shapes and
// collinear vertices accepted; a crossing or touching outline refused at the list).
SimplePolygon read_plan(const InputNode& node);

// One pair of the `isopound geometry overlap` file.
struct PolygonPair {
  std::string name;  // optional `name:`; empty when not given
  SimplePolygon a;  // convex or not
  SimplePolygon b;
};

// Reads a file holding `pairs:`, a list of {a: [[x, y], ...], b: [[x, y], ...], name: text}.
std::vector<PolygonPair> load_polygon_pairs_file(const std::string& path);

}  // namespace isopound
