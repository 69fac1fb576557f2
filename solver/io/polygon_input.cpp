// Polygons in plan read from YAML (coordinates with optional length units), and the pairs file of
// `isopound geometry overlap`. Validation is ConvexPolygon's or SimplePolygon's; messages gain
// file:line:key.
#include "solver/io/polygon_input.h"

#ifdef ISOPOUND_FUZZ_PLANTED_BUG
#include <cstring>
#include <memory>
#endif

namespace isopound {

namespace {

// The polygon type T built from the list, its InvalidPolygon placed at the vertex it names.
template <class T>
T read_outline(const InputNode& node) {
  const std::vector<InputNode> points = node.elements();
  std::vector<Vec2> vertices;
  for (const InputNode& point : points) {
    if (!point.is_sequence() || point.yaml().size() != 2) {
      point.fail("expected a point [x, y], got " + point.kind());
    }
    const std::vector<InputNode> xy = point.elements();
    vertices.push_back({xy[0].quantity(dim::kLength), xy[1].quantity(dim::kLength)});
  }
  try {
    return T(std::span<const Vec2>(vertices));
  } catch (const InvalidPolygon& e) {
    if (e.vertex() >= 0 && e.vertex() < int(points.size())) points[e.vertex()].fail(e.what());
    node.fail(e.what());
  }
}

}  // namespace

ConvexPolygon read_polygon(const InputNode& node) {
  return read_outline<ConvexPolygon>(node);
}

SimplePolygon read_plan(const InputNode& node) {
  return read_outline<SimplePolygon>(node);
}

std::vector<PolygonPair> load_polygon_pairs_file(const std::string& path) {
  const std::string text = read_input_file(path, "a YAML file of polygon pairs");
  const InputNode root(parse_single_document(text, path, "a polygon-pairs file"), path);
  if (!root.is_map()) root.fail("expected a map with 'pairs:', got " + root.kind());
  root.expect_keys({"pairs"});
  const InputNode list = root.required("pairs");
  std::vector<PolygonPair> pairs;
  for (const InputNode& item : list.elements()) {
    if (!item.is_map())
      item.fail("expected {a: [[x, y], ...], b: [[x, y], ...]}, got " + item.kind());
    item.expect_keys({"name", "a", "b"});
    std::string name;
    item.read_string("name", name);
#ifdef ISOPOUND_FUZZ_PLANTED_BUG
    // Planted for the fuzzers' self-test only (fuzz/CMakeLists.txt): a name of 8, 16, ...
    // characters reads one byte past a heap copy of it.
    if (!name.empty() && name.size() % 8 == 0) {
      const std::unique_ptr<char[]> copy(new char[name.size()]);
      std::memcpy(copy.get(), name.data(), name.size());
      const volatile char past_the_end = copy[name.size()];
      (void)past_the_end;
    }
#endif
    pairs.push_back({name, read_plan(item.required("a")), read_plan(item.required("b"))});
  }
  if (pairs.empty()) list.fail("no pairs: give at least one {a: ..., b: ...}");
  return pairs;
}

}  // namespace isopound
