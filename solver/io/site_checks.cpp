// The site checks of a model at rest (see site_checks.h). Each problem blames the key it
// concerns; the same function serves the reader (load_model) and isopound-pre.
#include "solver/io/site_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

#include "geometry/moat.h"
#include "geometry/overlap.h"
#include "geometry/plan_shape.h"
#include "solver/io/bumper_input.h"
#include "solver/structures/config3d.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding2d.h"
#include "solver/structures/pounding3d.h"
#include "solver/structures/struck_columns3d.h"

namespace isopound {
namespace {

constexpr double kGround = 0.01;  // m: levels below are at the ground
constexpr double kNoArea = 1e-9;  // m2: overlaps below this are touching, not overlapping

std::string fmt(const char* f, double v) {
  return format_number(f, v);
}
std::string metres(double v) {
  return metres_text(v);
}

ConvexPolygon polygon(const std::vector<Vec2>& v) {
  return ConvexPolygon(std::span<const Vec2>(v.data(), v.size()));
}

// Inside or on the boundary of a plan, within 1e-9 sqrt(area).
bool inside(const std::vector<Vec2>& plan, Vec2 p) {
  if (!is_convex_list(plan))
    return plan_contains(plan, p, 1e-9 * std::sqrt(plan_area_properties(plan).area));
  const ConvexPolygon poly = polygon(plan);
  const double tol = 1e-9 * std::sqrt(area_properties(poly).area);
  for (int i = 0; i < poly.size(); ++i) {
    const Vec2 a0 = poly[i], edge = poly[(i + 1) % poly.size()] - a0;
    if (cross(edge, p - a0) < -tol * std::sqrt(dot(edge, edge))) return false;
  }
  return true;
}

// The node to blame for a structure's placement: `adjacent`, `position`, else its item.
std::pair<InputNode, std::string> placement_node(const StructureMarks& m) {
  if (m.adjacent) return {*m.adjacent, ""};
  if (const auto p = m.item->find("position")) return {*p, ""};
  return {*m.item, "position"};
}

// Storey s (0-based): its list item, or `storeys:` (short form), or the structure's item.
const InputNode& storey_node(const StructureMarks& m, std::size_t s) {
  if (s < m.storey.size()) return m.storey[s];
  return m.storeys ? *m.storeys : *m.item;
}

// Column k of storey s: its `at` when listed, else its storey.
const InputNode& column_node(const StructureMarks& m, std::size_t s, std::size_t k) {
  if (s < m.column_at.size() && k < m.column_at[s].size() && m.column_at[s][k])
    return *m.column_at[s][k];
  return storey_node(m, s);
}

Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return a + t * d;
}

// Columns and bearings inside the slabs they join (building frame, as written).
void check_placement(const Building3DConfig& b, const StructureMarks& m, ProblemList& problems) {
  if (b.isolated && !b.bearings.empty()) {
    for (std::size_t k = 0; k < b.bearings.size(); ++k) {
      const std::size_t on = static_cast<std::size_t>(b.isolation_level);  // floor k, 1-based
      if (inside(b.base.plan, b.bearings[k].position) &&
          (on == 0 || inside(b.storeys[on - 1].floor.plan, b.bearings[k].position)))
        continue;
      const InputNode& where = k < m.bearing_at.size() && m.bearing_at[k] ? *m.bearing_at[k]
                               : m.bearings                               ? *m.bearings
                                                                          : *m.item;
      problems.error_at(where, "",
                        "bearing " + b.bearings[k].label + " is outside the base slab's plan" +
                            (on > 0 ? " or floor " + std::to_string(on) + "'s" : ""));
    }
  }
  // Short form: every storey alike; storey 1 stands for all (one message per column).
  const bool short_form = m.storeys && m.storeys->is_map();
  const std::size_t storeys =
      short_form ? std::min<std::size_t>(1, b.storeys.size()) : b.storeys.size();
  for (std::size_t s = 0; s < storeys; ++s) {
    // The storey over the isolation (k + 1) stands on the base slab.
    const bool on_base = b.isolated && s == static_cast<std::size_t>(b.isolation_level);
    const std::vector<Vec2>* below =
        on_base ? &b.base.plan : (s > 0 ? &b.storeys[s - 1].floor.plan : nullptr);
    const std::vector<Column3DConfig>& columns = b.storeys[s].columns;
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const Column3DConfig& c = columns[k];
      if (on_base && b.bearings.empty() && !inside(b.base.plan, c.position)) {
        problems.error_at(
            column_node(m, s, k), "",
            "column " + c.label + " (and the bearing under it) is outside the base slab's plan");
      } else if (!inside(b.storeys[s].floor.plan, c.position) ||
                 (below && !inside(*below, c.position))) {
        problems.error_at(column_node(m, s, k), "",
                          "column " + c.label + " of storey " + std::to_string(s + 1) +
                              " is outside its slab's plan");
      }
    }
  }
}

// Every centre of mass (centroid + eccentricity) inside its slab; one message per place where
// the eccentricity is written.
void check_centres_of_mass(const Building3DConfig& b, const StructureMarks& m,
                           ProblemList& problems) {
  std::vector<std::pair<const Diaphragm3DConfig*, std::string>> levels;
  std::vector<const InputNode*> level_nodes;
  if (b.isolated) {
    levels.push_back({&b.base, "the base"});
    level_nodes.push_back(m.base ? &*m.base : &*m.item);
  }
  for (std::size_t s = 0; s < b.storeys.size(); ++s) {
    levels.push_back({&b.storeys[s].floor, "floor " + std::to_string(s + 1)});
    level_nodes.push_back(&storey_node(m, s));
  }
  std::vector<std::string> blamed;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const Diaphragm3DConfig& d = *levels[i].first;
    const Vec2 centroid = plan_area_properties(d.plan).p_WC;
    const Vec2 p_M = centroid + d.eccentricity;
    if (inside(d.plan, p_M)) continue;
    std::optional<InputNode> where =
        level_nodes[i]->is_map() ? level_nodes[i]->find("eccentricity") : std::nullopt;
    if (!where) where = m.item->find("eccentricity");
    if (!where) where = *level_nodes[i];
    const std::string id = where->path();
    if (std::find(blamed.begin(), blamed.end(), id) != blamed.end()) continue;
    blamed.push_back(id);
    problems.error_at(*where, "",
                      "the centre of mass of " + levels[i].second + " of '" + b.name + "' at (" +
                          metres(p_M.x) + ", " + metres(p_M.y) +
                          ") in the building frame is outside its slab's plan (eccentricity (" +
                          metres(d.eccentricity.x) + ", " + metres(d.eccentricity.y) +
                          ") from the slab's centroid)");
  }
}

// Buildings placed by `adjacent: {to, side, gap}` (which places bounding boxes): the smallest
// clearance between floors of the two at equal levels, where they pound, must be the declared
// gap; every clearance of the pair is shown with it.
void check_adjacency(const ModelConfig& config, const std::vector<StructureMarks>& marks,
                     const SiteLimits& limits, std::vector<Clearance>& clearances,
                     ProblemList& problems) {
  for (std::size_t i = 0; i < config.structures3d.size(); ++i) {
    const Adjacency3DConfig& adj = config.structures3d[i].adjacent;
    if (adj.to.empty()) continue;
    const int me = static_cast<int>(i);
    const Clearance* nearest = nullptr;
    for (Clearance& c : clearances) {
      if (c.structure_a == c.structure_b || (c.structure_a != me && c.structure_b != me)) continue;
      const int other = c.structure_a == me ? c.structure_b : c.structure_a;
      if (config.structures3d.at(static_cast<std::size_t>(other)).name != adj.to) continue;
      c.declared = adj.gap;
      if (c.same_level && (!nearest || c.measured < nearest->measured)) nearest = &c;
    }
    if (!nearest || std::abs(nearest->measured - adj.gap) <= limits.gap_tolerance) continue;
    const InputNode& where = marks[i].adjacent ? *marks[i].adjacent : *marks[i].item;
    problems.error_at(where, "gap",
                      "the floors of '" + config.structures3d[i].name + "' and '" + adj.to +
                          "' that meet are " + metres(nearest->measured) +
                          " apart at the closest (" + nearest->a + " and " + nearest->b +
                          "), not at the declared gap of " + metres(adj.gap) +
                          " (adjacent places the bounding boxes of all their slabs)");
  }
}

// A column of the site between the elevations it joins.
struct ColumnSpan {
  int structure = 0;
  std::string label;  // "column A1 of storey 1 of 'building'"
  std::vector<Vec2> outline_W;
  double z_bottom = 0.0, z_top = 0.0;
};

std::vector<ColumnSpan> column_spans(const ModelConfig& config, const Site& site) {
  std::vector<ColumnSpan> spans;
  const auto elevation_of = [&](int structure, int level_index) {
    for (const PlanSlab& s : site.slabs)
      if (s.structure == structure && s.level_index == level_index) return s.elevation;
    return 0.0;
  };
  const auto add = [&](int structure, int storey, const PlanColumn& c, double z0, double z1) {
    const std::string& name = config.structures3d.at(static_cast<std::size_t>(structure)).name;
    spans.push_back(
        {structure,
         "column " + c.label + " of storey " + std::to_string(storey) + " of '" + name + "'",
         c.outline_W(), z0, z1});
  };
  for (std::size_t k = 0; k < site.ground_columns.size(); ++k) {
    const int structure = site.ground_columns_structure[k];
    add(structure, 1, site.ground_columns[k], 0.0, elevation_of(structure, 0));
  }
  for (const PlanSlab& s : site.slabs) {
    // The storey standing on level l (levels3d.h): l + 2 under the base slab, l + 1 from it up.
    const int base = base_level3d(config.structures3d.at(static_cast<std::size_t>(s.structure)));
    const int storey = s.level_index + (base >= 0 && s.level_index >= base ? 1 : 2);
    for (const PlanColumn& c : s.columns)
      add(s.structure, storey, c, s.elevation, elevation_of(s.structure, s.level_index + 1));
  }
  return spans;
}

// Columns of two structures over a common height standing in each other, and columns standing
// in another structure's slab: one message per pair of structures (the first case and a count).
void check_columns(const ModelConfig& config, const std::vector<StructureMarks>& marks,
                   const Site& site, const std::vector<ColumnSpan>& spans, const SiteLimits& limits,
                   ProblemList& problems) {
  const std::size_t n = config.structures3d.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      std::string first_columns, first_slab;
      int columns = 0, slabs = 0;
      for (const ColumnSpan& a : spans) {
        if (a.structure != static_cast<int>(i) && a.structure != static_cast<int>(j)) continue;
        const int other =
            a.structure == static_cast<int>(i) ? static_cast<int>(j) : static_cast<int>(i);
        for (const ColumnSpan& b : spans) {
          if (a.structure != static_cast<int>(i) || b.structure != static_cast<int>(j)) continue;
          if (std::min(a.z_top, b.z_top) - std::max(a.z_bottom, b.z_bottom) <=
              limits.level_tolerance)
            continue;
          const double area = plan_overlap_area(a.outline_W, b.outline_W);
          if (area <= kNoArea) continue;
          if (columns++ == 0)
            first_columns = a.label + " and " + b.label + " share " + fmt("%.4f m2", area);
        }
        for (const PlanSlab& s : site.slabs) {
          if (s.structure != other || s.elevation < a.z_bottom - limits.level_tolerance ||
              s.elevation > a.z_top + limits.level_tolerance)
            continue;
          const double area = plan_overlap_area(a.outline_W, s.plan_W);
          if (area <= kNoArea) continue;
          if (slabs++ == 0)
            first_slab = a.label + " stands in " + s.level + " of '" + s.name + "' (" +
                         fmt("%.4f m2", area) + ")";
        }
      }
      const auto [node, key] = placement_node(marks[j]);
      const std::string pair =
          "'" + config.structures3d[i].name + "' and '" + config.structures3d[j].name + "'";
      const auto more = [](int count, const char* what) {
        return count > 1 ? " (and " + std::to_string(count - 1) + " more " + what + ")"
                         : std::string();
      };
      if (columns > 0)
        problems.error_at(node, key,
                          "columns of " + pair + " stand in each other at rest: " + first_columns +
                              more(columns, "pairs") +
                              " (columns are drawn as b x h rectangles from I11 and I22; "
                              "place the structures apart, or make their slabs reach past "
                              "the columns)");
      if (slabs > 0)
        problems.error_at(node, key,
                          "a column of one of " + pair + " stands in a slab of the other at " +
                              "rest: " + first_slab + more(slabs, "cases"));
    }
}

}  // namespace

std::vector<StructureMarks> structure_marks(const InputNode& structures) {
  std::vector<StructureMarks> out;
  if (!structures.is_sequence()) return out;
  for (const InputNode& item : structures.elements()) {
    StructureMarks m;
    m.item = item;
    if (item.is_map()) {
      m.storeys = item.find("storeys");
      m.base = item.find("base");
      m.bearings = item.find("bearings");
      m.walls = item.find("walls");
      m.adjacent = item.find("adjacent");
    }
    if (m.storeys && m.storeys->is_sequence()) {
      for (const InputNode& s : m.storeys->elements()) {
        m.storey.push_back(s);
        std::vector<std::optional<InputNode>> at;
        const auto columns = s.is_map() ? s.find("columns") : std::nullopt;
        if (columns && columns->is_sequence())
          for (const InputNode& c : columns->elements())
            at.push_back(c.is_map() ? c.find("at") : std::nullopt);
        m.column_at.push_back(at);
      }
    }
    if (m.bearings && m.bearings->is_sequence())
      for (const InputNode& b : m.bearings->elements())
        m.bearing_at.push_back(b.is_map() ? b.find("at") : std::nullopt);
    out.push_back(m);
  }
  return out;
}

SiteLimits site_limits(const ModelConfig& model) {
  SiteLimits limits;
  limits.reach = model.contact3d.search_distance;
  limits.level_tolerance = model.contact3d.elevation_tolerance;
  return limits;
}

std::string side_name(Vec2 n) {
  if (std::abs(n.x) >= std::abs(n.y)) return n.x >= 0 ? "east" : "west";
  return n.y >= 0 ? "north" : "south";
}

void closest_points(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Vec2& p_a, Vec2& p_b) {
  // Every vertex-edge pair; those within round-off of the smallest distance are averaged, so two
  // parallel facing edges give the middle of their common stretch (where a dimension belongs).
  struct Pair {
    Vec2 a, b;
    double d;
  };
  std::vector<Pair> pairs;
  const auto scan = [&](const std::vector<Vec2>& points, const std::vector<Vec2>& edges,
                        bool points_are_a) {
    for (Vec2 p : points)
      for (std::size_t i = 0; i < edges.size(); ++i) {
        const Vec2 q = closest_on_segment(p, edges[i], edges[(i + 1) % edges.size()]);
        const double d = std::sqrt(dot(q - p, q - p));
        pairs.push_back(points_are_a ? Pair{p, q, d} : Pair{q, p, d});
      }
  };
  scan(a, b, true);
  scan(b, a, false);
  double best = std::numeric_limits<double>::infinity();
  for (const Pair& p : pairs) best = std::min(best, p.d);
  Vec2 sa, sb;
  int n = 0;
  for (const Pair& p : pairs)
    if (p.d <= best + 1e-9 * (1.0 + best)) {
      sa = sa + p.a;
      sb = sb + p.b;
      ++n;
    }
  p_a = (1.0 / n) * sa;
  p_b = (1.0 / n) * sb;
}

std::vector<Clearance> check_site3d(const ModelConfig& config,
                                    const std::vector<StructureMarks>& marks, const Site& site,
                                    const SiteLimits& limits, ProblemList& problems) {
  const std::size_t n = config.structures3d.size();
  std::vector<Clearance> clearances;
  if (marks.size() != n) return clearances;  // `structures:` was not a list: the reader said so

  // Per structure: columns, bearings and centres of mass inside their slabs.
  for (std::size_t i = 0; i < n; ++i) {
    check_placement(config.structures3d[i], marks[i], problems);
    check_centres_of_mass(config.structures3d[i], marks[i], problems);
  }

  // Structures overlapping at rest, and the nearest approach of every pair (any levels).
  std::vector<std::vector<double>> nearest(n, std::vector<double>(n, 1e300));
  for (std::size_t i = 0; i < site.slabs.size(); ++i)
    for (std::size_t j = i + 1; j < site.slabs.size(); ++j) {
      const PlanSlab& a = site.slabs[i];
      const PlanSlab& b = site.slabs[j];
      if (a.structure == b.structure) continue;
      const Separation sep = plan_separation(a.plan_W, b.plan_W);
      double& near = nearest[a.structure][b.structure];
      near = std::min(near, sep.distance);
      nearest[b.structure][a.structure] = near;
      if (std::abs(a.elevation - b.elevation) < limits.level_tolerance) {
        Clearance c{a.name + "/" + a.level,
                    b.name + "/" + b.level,
                    a.structure,
                    b.structure,
                    side_name(sep.n_AB),
                    sep.distance,
                    -1.0,
                    a.elevation,
                    true,
                    {},
                    {}};
        if (sep.distance > 0) closest_points(a.plan_W, b.plan_W, c.p_WA, c.p_WB);
        clearances.push_back(c);
      }
    }
  // Pairs of structures with no slabs at equal levels: their nearest approach (any levels).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      bool listed = false;
      for (const Clearance& c : clearances)
        listed = listed || (c.a.rfind(config.structures3d[i].name + "/", 0) == 0 &&
                            c.b.rfind(config.structures3d[j].name + "/", 0) == 0);
      if (listed) continue;
      const PlanSlab *best_a = nullptr, *best_b = nullptr;
      Separation best{1e300, {}};
      for (const PlanSlab& a : site.slabs)
        for (const PlanSlab& b : site.slabs) {
          if (a.structure != static_cast<int>(i) || b.structure != static_cast<int>(j)) continue;
          const Separation sep = plan_separation(a.plan_W, b.plan_W);
          if (sep.distance < best.distance) best = sep, best_a = &a, best_b = &b;
        }
      if (!best_a) continue;
      Clearance c{best_a->name + "/" + best_a->level,
                  best_b->name + "/" + best_b->level,
                  best_a->structure,
                  best_b->structure,
                  side_name(best.n_AB),
                  best.distance,
                  -1.0,
                  best_a->elevation,
                  false,
                  {},
                  {}};
      if (best.distance > 0) closest_points(best_a->plan_W, best_b->plan_W, c.p_WA, c.p_WB);
      clearances.push_back(c);
    }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      // The largest overlap of any two of their slabs (areas at the same elevation or not: in
      // plan the two buildings would stand in each other).
      double area = 0.0, depth = 0.0;
      std::string where;
      for (const PlanSlab& a : site.slabs)
        for (const PlanSlab& b : site.slabs) {
          if (a.structure != static_cast<int>(i) || b.structure != static_cast<int>(j)) continue;
          const double shared = plan_overlap_area(a.plan_W, b.plan_W);
          if (shared > area) {
            area = shared;
            depth = -plan_separation(a.plan_W, b.plan_W).distance;
            where = a.level + " of '" + a.name + "' and " + b.level + " of '" + b.name + "'";
          }
        }
      if (area > kNoArea) {
        const auto [node, key] = placement_node(marks[j]);
        problems.error_at(node, key,
                          "structures '" + config.structures3d[i].name + "' and '" +
                              config.structures3d[j].name + "' overlap at rest: " + where +
                              " share " + fmt("%.3f m2", area) + " (" + metres(depth) + " deep)");
      }
    }
  const std::vector<ColumnSpan> spans = column_spans(config, site);
  check_columns(config, marks, site, spans, limits, problems);
  check_slab_bumpers(config, marks, site, limits.level_tolerance, problems);

  // Walls: the clearance to the base slab they surround, measured per side against the declared
  // gap; no wall may stand in another structure's slab (up to its height) or on its columns.
  for (const PlanWall& w : site.walls) {
    const StructureMarks& m = marks.at(static_cast<std::size_t>(w.building));
    const InputNode& where = m.walls ? *m.walls : *m.item;
    // The level the walls face (the base slab unless walls.level says otherwise).
    const int faced = walls_level3d(config.structures3d.at(static_cast<std::size_t>(w.building)));
    for (const PlanSlab& s : site.slabs) {
      if (s.structure == w.building && s.level_index == faced) {
        const Separation sep = plan_separation(s.plan_W, w.plan_W);
        Clearance c;
        c.a = s.name + "/" + s.level;
        c.b = w.name;
        c.structure_a = c.structure_b = w.building;
        c.side = w.side;
        c.measured = sep.distance;
        c.declared = w.declared_gap;
        if (sep.distance > 0) closest_points(s.plan_W, w.plan_W, c.p_WA, c.p_WB);
        if (w.along_outline && sep.distance > 0) {
          // Along its normal over its own extent (at rest apart: a wall in the slab is caught by
          // the distance above).
          // (Nothing of the slab in front of it, as a polyline's wall may stand: the distance.)
          const NormalClearance along = normal_clearance(s.plan_W, w.plan_W, w.normal_W);
          if (std::isfinite(along.clearance)) {
            c.measured = along.clearance;
            c.p_WA = along.p_WA;
            c.p_WB = along.p_WA + along.clearance * w.normal_W;
          }
        }
        clearances.push_back(c);
        if (w.declared_gap >= 0 && std::abs(c.measured - w.declared_gap) > limits.gap_tolerance)
          problems.error_at(
              where, "gap",
              "the " + w.side + " wall of '" + w.structure + "' stands " + metres(c.measured) +
                  " from its " + (s.level == "base" ? std::string("base slab") : s.level) +
                  " (measured), not at " + "the declared gap of " + metres(w.declared_gap));
      } else if (s.structure != w.building && s.elevation >= w.elevation - limits.level_tolerance &&
                 s.elevation <= w.elevation + w.height + limits.level_tolerance) {
        const double shared = plan_overlap_area(s.plan_W, w.plan_W);
        if (shared > kNoArea)
          problems.error_at(where, "",
                            "the " + w.side + " wall of '" + w.structure + "' overlaps " + s.level +
                                " of '" + s.name + "' at rest (" + fmt("%.3f m2", shared) + ")");
      }
    }
    // A wall raised to a level above the ground (isolated above a storey): no column whose
    // storey spans the wall's height [elevation - height, elevation] may stand in it.
    if (w.elevation > limits.level_tolerance)
      for (const ColumnSpan& c : spans)
        if (c.z_top > w.elevation - w.height + limits.level_tolerance &&
            c.z_bottom < w.elevation - limits.level_tolerance &&
            plan_overlap_area(c.outline_W, w.plan_W) > 0)
          problems.error_at(where, "",
                            "the " + w.side + " wall of '" + w.structure + "' cuts " + c.label);
    for (std::size_t k = 0; k < site.ground_columns.size() && w.elevation <= limits.level_tolerance;
         ++k) {
      const Overlap o = overlap_of(polygon(site.ground_columns[k].outline_W()), polygon(w.plan_W));
      if (o.area > 0)
        problems.error_at(where, "",
                          "the " + w.side + " wall of '" + w.structure + "' stands on column " +
                              site.ground_columns[k].label + " of '" +
                              config.structures3d.at(site.ground_columns_structure[k]).name + "'");
    }
  }
  check_adjacency(config, marks, limits, clearances, problems);

  // Floors of pounding pairs at equal levels: every floor of one within the other's height
  // must meet a floor of the other.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || nearest[i][j] > limits.reach) continue;
      double top_j = 0.0;
      for (const PlanSlab& b : site.slabs)
        if (b.structure == static_cast<int>(j)) top_j = std::max(top_j, b.elevation);
      for (const PlanSlab& a : site.slabs) {
        if (a.structure != static_cast<int>(i) || a.elevation < kGround ||
            a.elevation > top_j + limits.level_tolerance)
          continue;
        const PlanSlab* partner = nullptr;
        double dz = 1e300;
        for (const PlanSlab& b : site.slabs)
          if (b.structure == static_cast<int>(j) && std::abs(b.elevation - a.elevation) < dz) {
            dz = std::abs(b.elevation - a.elevation);
            partner = &b;
          }
        if (!partner || dz < limits.level_tolerance) continue;
        // Issue 26: strictly between two floors of a storey of j whose columns are described
        // (struck_columns:), it strikes those columns (struck_columns3d.h), in elastic storeys.
        const Building3DConfig& bj = config.structures3d[j];
        if (bj.struck_columns.given) {
          if (const int k = storey_between_floors(bj, a.elevation, limits.level_tolerance)) {
            for (const Column3DConfig& c : bj.storeys[static_cast<std::size_t>(k) - 1].columns)
              if (c.hysteresis.yields()) {
                problems.error_at(*marks[j].item, "struck_columns",
                                  a.level + " of '" + a.name + "' at " + metres(a.elevation) +
                                      " strikes storey " + std::to_string(k) + " of '" + bj.name +
                                      "', whose column " + c.label +
                                      " yields: struck columns are modelled in elastic storeys "
                                      "only");
                break;
              }
            continue;
          }
        }
        // The storey under floor f (0-based f - 1); the base slab: the building's entry.
        const int base = base_level3d(config.structures3d[i]);
        const int storey = a.level_index == base
                               ? -1
                               : a.level_index - (base >= 0 && a.level_index > base ? 1 : 0);
        const InputNode& where =
            storey >= 0 ? storey_node(marks[i], static_cast<std::size_t>(storey)) : *marks[i].item;
        problems.error_at(where, "",
                          a.level + " of '" + a.name + "' at " + metres(a.elevation) +
                              " has no floor of '" + partner->name + "' at its level (nearest: " +
                              partner->level + " at " + metres(partner->elevation) + "), " +
                              (nearest[i][j] > 0 ? metres(nearest[i][j]) + " away"
                                                 : std::string("overlapping it")) +
                              ": it would pound that building's columns, which the model "
                              "does not represent (floors of pounding pairs must be at equal "
                              "levels, or describe its struck columns with struck_columns: {M_y}, "
                              "docs/floor-to-column.md)");
      }
    }
  // One struck point per column: a column two slabs strike (two neighbours' floors at different
  // heights against a corner column) would need a column with two nodes.
  const bool any_struck =
      std::any_of(config.structures3d.begin(), config.structures3d.end(),
                  [](const Building3DConfig& b) { return b.struck_columns.given; });
  if (any_struck && config.contact3d.pounding) {
    const std::vector<StruckColumnSite> sites = struck_column_sites(config);
    for (std::size_t s = 0; s < sites.size(); ++s)
      for (std::size_t r = 0; r < s; ++r)
        if (sites[r].struck == sites[s].struck && sites[r].storey == sites[s].storey &&
            sites[r].column == sites[s].column) {
          problems.error_at(
              *marks[static_cast<std::size_t>(sites[s].struck)].item, "struck_columns",
              "column " + sites[s].column_label + " of storey " + std::to_string(sites[s].storey) +
                  " of '" + sites[s].struck_name + "' is struck by " + sites[r].striker_name + "/" +
                  sites[r].slab_level + " and by " + sites[s].striker_name + "/" +
                  sites[s].slab_level +
                  ": one struck point per column is modelled (widen a gap or "
                  "align those floors)");
          break;
        }
  }
  return clearances;
}

void check_site2d(const ModelConfig& config, const std::vector<InputNode>& neighbours,
                  ProblemList& problems) {
  // Neighbours: a level of one within the other's height meets a level of the other
  // (pounding2d.cpp pairs levels within 1 mm) or, when the other describes its facing column
  // line (columns:), may strike its columns between two floors. Elevations are the levels' own
  // (an isolated slab raised above a storey raises the floors above it).
  const BuildingConfig& b = config.building;
  if (b.floors.empty()) return;
  const std::vector<double> z_main = level_elevations(b);
  // "floor 2", or "the base slab" (level order of level_elevations).
  const auto level_name = [](const BuildingConfig& x, std::size_t level) {
    if (is_base_level(x, static_cast<int>(level))) return std::string("the base slab");
    int floor = 0;
    for (std::size_t j = 0; j <= level; ++j) floor += is_base_level(x, static_cast<int>(j)) ? 0 : 1;
    return "floor " + std::to_string(floor);
  };
  for (std::size_t k = 0; k < config.neighbours.size() && k < neighbours.size(); ++k) {
    const NeighbourConfig& neighbour = config.neighbours[k];
    const BuildingConfig& nb = neighbour.building;
    if (nb.floors.empty()) continue;
    std::vector<double> z_other = level_elevations(nb);
    for (double& z : z_other) z += neighbour.ground_level;
    const InputNode& at = neighbours[k];
    for (int pass = 0; pass < 2; ++pass) {
      const BuildingConfig& a = pass == 0 ? b : nb;
      const BuildingConfig& o = pass == 0 ? nb : b;
      const double ground_o = pass == 0 ? neighbour.ground_level : 0.0;
      const std::vector<double>& za = pass == 0 ? z_main : z_other;
      const std::vector<double>& zo = pass == 0 ? z_other : z_main;
      std::vector<int> struck;
      for (std::size_t f = 0; f < za.size(); ++f) {
        const FacedPart part = faced_part(o, zo, ground_o, za[f]);
        const std::string what =
            level_name(a, f) + " of '" + a.name + "' at " + metres(za[f]) + " ";
        using Kind = FacedPart::Kind;
        if (part.kind == Kind::kBelowGround) {
          problems.error_at(at, "ground_level",
                            what + "faces '" + o.name + "' below its ground (" + metres(ground_o) +
                                "): its foundation is outside the model");
        } else if (part.kind == Kind::kIsolationGap) {
          problems.error_at(at, "",
                            what + "faces the isolators of '" + o.name +
                                "': slab-to-isolator contact is outside the model");
        } else if (part.kind == Kind::kStorey && !o.columns.given) {
          double dz = 1e300, nearest = 0;
          for (double z : zo)
            if (std::abs(z - za[f]) < dz) dz = std::abs(z - za[f]), nearest = z;
          problems.error_at(at, "",
                            what + "has no floor of '" + o.name + "' at its level (nearest " +
                                metres(nearest) +
                                "): it would pound that building's columns; describe them with "
                                "columns: {count, E, I, M_y} (docs/floor-to-column.md)");
        } else if (part.kind == Kind::kStorey) {
          if (o.floors[static_cast<std::size_t>(part.floor) - 1].hysteresis.yields())
            problems.error_at(at, "",
                              what + "strikes yielding storey " + std::to_string(part.floor) +
                                  " of '" + o.name +
                                  "': struck columns are modelled in elastic storeys only");
          if (std::find(struck.begin(), struck.end(), part.floor) != struck.end())
            problems.error_at(at, "",
                              what + "strikes storey " + std::to_string(part.floor) + " of '" +
                                  o.name +
                                  "', which another level strikes already: one struck point per "
                                  "storey");
          struck.push_back(part.floor);
        }
      }
    }
  }
}

}  // namespace isopound
