// The lenient scan in front of the solver's reader: plans, columns and bearings read with the same
// InputNode calls as solver/io/model_input3d.cpp, every placement problem collected, and the YAML
// repaired so that the reader gets through and the checks that need the whole model run too.
#include "geometry/pre/model_scan.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <span>

#include "geometry/convex_polygon.h"
#include "solver/io/model_input.h"
#include "solver/io/model_input3d.h"
#include "solver/structures/config3d.h"

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

// Andrew's monotone chain, counter-clockwise, collinear points dropped.
std::vector<Vec2> convex_hull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// The reader's test (model_input3d.cpp): inside or on the boundary, within 1e-9 sqrt(area).
// The reader's rules between structures (after issue 16): reported by check_site() for all pairs.
bool between_structures(const std::string& detail) {
  for (const char* what : {"overlap at rest", "at rest (by", "faces structure"})
    if (detail.find(what) != std::string::npos) return true;
  return false;
}

bool inside(const std::vector<Vec2>& plan, Vec2 p) {
  const ConvexPolygon poly(std::span<const Vec2>(plan.data(), plan.size()));
  const double tol = 1e-9 * std::sqrt(area_properties(poly).area);
  for (int i = 0; i < poly.size(); ++i) {
    const Vec2 a0 = poly[i], edge = poly[(i + 1) % poly.size()] - a0;
    if (cross(edge, p - a0) < -tol * std::sqrt(dot(edge, edge))) return false;
  }
  return true;
}

struct Scanner {
  ProblemList& problems;
  bool outside_reported = false;  // the reader's "is outside" error then repeats one of ours

  // plan: {rectangle} or {polygon}; a polygon that is not convex is reported as the reader
  // does and replaced (in the YAML) by its convex hull.
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
               const ConvexPolygon check(std::span<const Vec2>(v.data(), v.size()));
               return v;
             } catch (const InvalidPolygon& e) {
               const std::string what = std::string("not a convex polygon: ") + e.what();
               if (e.vertex() >= 0 && e.vertex() < static_cast<int>(v.size()))
                 problems.error_at(poly->elements()[e.vertex()], "", what);
               else
                 problems.error_at(*poly, "", what);
             }
             std::vector<Vec2> hull = convex_hull(v);
             try {
               const ConvexPolygon check(std::span<const Vec2>(hull.data(), hull.size()));
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

  struct Column {
    std::string label;
    Vec2 p;
    std::optional<InputNode> at;  // list form: the item (to blame and to drop)
  };

  void structure(const InputNode& item, StructureMarks& marks) {
    marks.item = item;
    if (!item.is_map()) return;
    marks.storeys = item.find("storeys");
    marks.base = item.find("base");
    marks.bearings = item.find("bearings");
    marks.walls = item.find("walls");
    marks.adjacent = item.find("adjacent");
    const bool isolated = attempt([&] {
                            bool b = true;
                            item.read_boolean("isolated", b);
                            return b;
                          }).value_or(true);
    // Grid columns (A1.., as the reader names them) and the default plan.
    std::vector<std::pair<std::string, Vec2>> grid;
    if (const auto g = item.find("grid")) {
      attempt([&] {
        std::vector<double> lines[2];
        const char* keys[2] = {"bays_x", "bays_y"};
        for (int d = 0; d < 2; ++d) {
          lines[d].push_back(0.0);
          for (const InputNode& b : g->required(keys[d]).elements())
            lines[d].push_back(lines[d].back() + b.quantity(dim::kLength, Bound::kPositive));
        }
        Vec2 origin{-lines[0].back() / 2, -lines[1].back() / 2};
        if (const auto o = g->find("origin")) origin = read_point(*o);
        for (std::size_t iy = 0; iy < lines[1].size(); ++iy)
          for (std::size_t ix = 0; ix < lines[0].size(); ++ix) {
            std::string label(1, static_cast<char>('A' + ix));
            label.append(std::to_string(iy + 1));
            grid.push_back({label, {origin.x + lines[0][ix], origin.y + lines[1][iy]}});
          }
        return 0;
      });
    }
    std::optional<std::vector<Vec2>> plan_default;
    if (const auto p = item.find("plan"))
      plan_default = plan(*p);
    else if (!grid.empty())
      plan_default = std::vector<Vec2>{grid.front().second,
                                       {grid.back().second.x, grid.front().second.y},
                                       grid.back().second,
                                       {grid.front().second.x, grid.back().second.y}};
    const auto plan_of = [&](const InputNode& n) {
      if (const auto p = n.find("plan")) return plan(*p);
      return plan_default;
    };
    std::optional<std::vector<Vec2>> base_plan;
    if (isolated && marks.base && marks.base->is_map()) base_plan = plan_of(*marks.base);

    // Storeys: per storey its floor plan and columns.
    struct Storey {
      std::optional<std::vector<Vec2>> plan;
      std::vector<Column> columns;
      InputNode where;
      std::optional<InputNode> columns_node;
    };
    std::vector<Storey> storeys;
    if (marks.storeys && marks.storeys->is_sequence()) {
      for (const InputNode& s : marks.storeys->elements()) {
        marks.storey.push_back(s);
        if (!s.is_map()) continue;
        Storey st{plan_of(s), {}, s, s.find("columns")};
        if (st.columns_node && st.columns_node->is_sequence()) {
          int n = 0;
          for (const InputNode& c : st.columns_node->elements()) {
            ++n;
            const auto at = c.is_map() ? c.find("at") : std::nullopt;
            if (!at) continue;
            const auto p = attempt([&] { return read_point(*at); });
            if (!p) continue;
            std::string label = "C" + std::to_string(n);
            if (const auto l = c.find("label"))
              label = attempt([&] { return l->string(); }).value_or(label);
            st.columns.push_back({label, *p, c});
          }
        } else if (!st.columns_node) {
          for (const auto& [label, p] : grid) st.columns.push_back({label, p, std::nullopt});
        }
        storeys.push_back(st);
      }
    } else if (marks.storeys && marks.storeys->is_map()) {
      // Short form: every storey alike; storey 1 stands for all (one message per column).
      const int count =
          attempt([&] { return marks.storeys->required("count").integer(1, 200); }).value_or(1);
      marks.storey.assign(static_cast<std::size_t>(count), *marks.storeys);
      Storey st{plan_default, {}, *marks.storeys, std::nullopt};
      for (const auto& [label, p] : grid) st.columns.push_back({label, p, std::nullopt});
      storeys.push_back(st);
    }

    // Bearings inside the base slab (the reader's messages, each at its item).
    const bool bearing_list = marks.bearings && marks.bearings->is_sequence();
    if (isolated && base_plan && bearing_list) {
      std::vector<YAML::Node> kept;
      const std::vector<InputNode> items = marks.bearings->elements();
      int n = 0;
      for (const InputNode& b : items) {
        ++n;
        const auto at = b.is_map() ? b.find("at") : std::nullopt;
        const auto p = at ? attempt([&] { return read_point(*at); }) : std::nullopt;
        std::string label = "B" + std::to_string(n);
        if (const auto l = b.is_map() ? b.find("label") : std::nullopt)
          label = attempt([&] { return l->string(); }).value_or(label);
        if (p && !inside(*base_plan, *p)) {
          problems.error_at(*at, "", "bearing " + label + " is outside the base slab's plan");
          outside_reported = true;
          continue;
        }
        YAML::Node y = b.yaml();
        if (b.is_map() && !b.has("label")) y["label"] = label;  // keep the numbering
        kept.push_back(y);
      }
      if (!kept.empty() && kept.size() < items.size()) {
        YAML::Node seq(YAML::NodeType::Sequence);
        for (const YAML::Node& y : kept) seq.push_back(y);
        YAML::Node writable = item.yaml();
        writable["bearings"] = seq;
      }
    }
    // Columns inside the floor they carry and the level they stand on.
    for (std::size_t s = 0; s < storeys.size(); ++s) {
      Storey& st = storeys[s];
      const std::optional<std::vector<Vec2>>* below =
          s > 0 ? &storeys[s - 1].plan : (isolated ? &base_plan : nullptr);
      std::vector<YAML::Node> kept;
      for (const Column& c : st.columns) {
        bool out = false;
        if (s == 0 && isolated && !bearing_list && base_plan && !inside(*base_plan, c.p)) {
          problems.error_at(
              c.at ? *c.at : st.where, c.at ? "at" : "",
              "column " + c.label + " (and the bearing under it) is outside the base slab's plan");
          out = true;
        } else if ((st.plan && !inside(*st.plan, c.p)) ||
                   (below && *below && !inside(**below, c.p))) {
          problems.error_at(c.at ? *c.at : st.where, c.at ? "at" : "",
                            "column " + c.label + " of storey " + std::to_string(s + 1) +
                                " is outside its slab's plan");
          out = true;
        }
        outside_reported = outside_reported || out;
        if (!c.at || out) continue;
        YAML::Node y = c.at->yaml();
        if (!c.at->has("label")) y["label"] = c.label;
        kept.push_back(y);
      }
      if (st.columns_node && !kept.empty() && kept.size() < st.columns.size()) {
        YAML::Node seq(YAML::NodeType::Sequence);
        for (const YAML::Node& y : kept) seq.push_back(y);
        YAML::Node writable = st.where.yaml();
        writable["columns"] = seq;
      }
    }
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
      for (const InputNode& item : s->elements()) {
        m.structures.emplace_back();
        scanner.structure(item, m.structures.back());
      }
    } else if (const auto b = m.root->find("building")) {
      m.building = b;
      if (b->is_map()) m.floors = b->find("floors");
      if (const auto n = m.root->find("neighbours"); n && n->is_sequence())
        m.neighbours = n->elements();
    }
  }
  // The structures alone first (read_structures3d: every per-structure rule of the reader),
  // then the whole model. When the whole model stops only at a rule between structures
  // (overlap at rest, levels of neighbours), which check_site() reports for every pair, the
  // rest of the model is read with the first structure alone and the structures put back.
  std::optional<std::vector<Building3DConfig>> structures;
  const auto report = [&](const InputError& e) {
    if (!(scanner.outside_reported && e.detail().find("is outside") != std::string::npos))
      problems.error(e.what());
  };
  if (m.is3d) {
    try {
      structures = read_structures3d(m.root->required("structures"));
    } catch (const InputError& e) {
      report(e);
    }
  }
  try {
    m.config = load_model(root, path, fs::path(path).parent_path().string());
  } catch (const InputError& e) {
    if (structures && between_structures(e.detail())) {
      YAML::Node first = YAML::Clone(root);
      YAML::Node one(YAML::NodeType::Sequence);
      one.push_back(first["structures"][0]);
      first["structures"] = one;
      try {
        m.config = load_model(first, path, fs::path(path).parent_path().string());
        m.config->structures3d = *structures;
      } catch (const InputError& again) {
        report(again);
      }
    } else {
      report(e);  // the same message as the structures-alone read's is kept once
    }
  }
  // Implausible values (solver/io/plausibility.h) are warnings here too: --strict refuses them.
  if (m.config)
    for (const std::string& w : m.config->warnings) problems.warning(w);
  return m;
}

}  // namespace isopound::pre
