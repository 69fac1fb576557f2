// The scan in front of the solver's reader: plans read with the same InputNode calls as
// solver/io/model_input3d.cpp, a non-convex polygon reported as the reader does and replaced (in
// the YAML) by its hull so that the reader gets through and the site checks run too.
#include "geometry/pre/model_scan.h"
#include "geometry/plan_shape.h"

#include <algorithm>
#include <filesystem>
#include <span>

#include "geometry/convex_polygon.h"
#include "solver/io/model_input.h"

namespace isopound::pre {
namespace {

namespace fs = std::filesystem;

// Runs `f`; an InputError (a structural problem the reader will report itself) gives nullopt.
template <typename F>
auto attempt(F f) -> std::optional<decltype(f())> {
  try {
    return f();
  } catch (const InputError&) {
    return std::nullopt;
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
}

Vec2 read_point(const InputNode& node) {
  if (!node.is_sequence() || node.elements().size() != 2) node.fail("expected [x, y]");
  const std::vector<InputNode> e = node.elements();
  return {e[0].quantity(dim::kLength), e[1].quantity(dim::kLength)};
}

struct Scanner {
  ProblemList& problems;

  // plan: {rectangle} or {polygon}; a polygon that is not a simple outline is reported as the
  // reader does and replaced (in the YAML) by its convex hull.
  std::optional<std::vector<Vec2>> plan(const InputNode& node) {
    return attempt([&]() -> std::optional<std::vector<Vec2>> {
             if (const auto rect = node.find("rectangle")) {
               const std::vector<InputNode> e = rect->elements();
               if (e.size() != 2) return std::nullopt;
               const double lx = e[0].quantity(dim::kLength, Bound::kPositive);
               const double ly = e[1].quantity(dim::kLength, Bound::kPositive);
               return std::vector<Vec2>{
                   {-lx / 2, -ly / 2}, {lx / 2, -ly / 2}, {lx / 2, ly / 2}, {-lx / 2, ly / 2}};
             }
             const auto poly = node.find("polygon");
             if (!poly || !poly->is_sequence()) return std::nullopt;
             std::vector<Vec2> v;
             for (const InputNode& p : poly->elements()) v.push_back(read_point(p));
             try {
               // Any simple outline (L, T, U plans: issue 40), as the solver reads it.
               const SimplePolygon check(std::span<const Vec2>(v.data(), v.size()));
               return v;
             } catch (const InvalidPolygon& e) {
               const std::string what = std::string("not a simple polygon: ") + e.what();
               if (e.vertex() >= 0 && e.vertex() < static_cast<int>(v.size()))
                 problems.error_at(poly->elements()[e.vertex()], "", what);
               else
                 problems.error_at(*poly, "", what);
             }
             std::vector<Vec2> hull;
             try {
               const ConvexPolygon h = convex_hull(v);
               hull.assign(h.vertices().begin(), h.vertices().end());
             } catch (const InvalidPolygon&) {
               return std::nullopt;  // degenerate: nothing to go on with
             }
             YAML::Node seq(YAML::NodeType::Sequence);
             for (Vec2 p : hull) {
               YAML::Node point(YAML::NodeType::Sequence);
               point.push_back(p.x);
               point.push_back(p.y);
               seq.push_back(point);
             }
             YAML::Node writable = node.yaml();
             writable["polygon"] = seq;
             return hull;
           })
        .value_or(std::nullopt);
  }

  // Every plan of a structure item: its own, the base's and each listed storey's.
  void structure(const InputNode& item) {
    if (!item.is_map()) return;
    if (const auto p = item.find("plan")) plan(*p);
    if (const auto base = item.find("base"); base && base->is_map())
      if (const auto p = base->find("plan")) plan(*p);
    if (const auto storeys = item.find("storeys"); storeys && storeys->is_sequence())
      for (const InputNode& s : storeys->elements())
        if (const auto p = s.is_map() ? s.find("plan") : std::nullopt) plan(*p);
  }
};

}  // namespace

ScannedModel scan_model(const std::string& path, ProblemList& problems) {
  ScannedModel m;
  m.path = path;
  YAML::Node root;
  try {
    const std::string text = read_input_file(path, "a YAML model file");
    root = parse_single_document(text, path, "a model file");
  } catch (const InputError& e) {
    problems.error(e.what());
    return m;
  }
  m.root = InputNode(root, path);
  Scanner scanner{problems};
  if (root.IsMap()) {
    if (const auto s = m.root->find("structures"); s && s->is_sequence()) {
      m.is3d = true;
      for (const InputNode& item : s->elements()) scanner.structure(item);
      m.structures = structure_marks(*s);
    } else if (const auto b = m.root->find("building")) {
      m.building = b;
      if (b->is_map()) m.floors = b->find("floors");
      if (const auto n = m.root->find("neighbours"); n && n->is_sequence())
        m.neighbours = n->elements();
    }
  }
  // The site checks' problems are collected by the reader itself; any other error stops it.
  try {
    m.config = load_model(root, path, fs::path(path).parent_path().string(), nullptr, &problems);
  } catch (const InputError& e) {
    problems.error(e.what());  // a repeat of the scan's own (non-convex plan) is kept once
  }
  // Implausible values (solver/io/plausibility.h) are warnings here too: --strict refuses them.
  if (m.config)
    for (const std::string& w : m.config->warnings) problems.warning(w);
  return m;
}

}  // namespace isopound::pre
