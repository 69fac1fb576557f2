// isopound-pre's model checks. Each problem blames the key it concerns (nodes kept by the scan).
#include "geometry/pre/checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>

#include "geometry/overlap.h"
#include "solver/structures/config3d.h"
#include "solver/structures/pounding3d.h"  // site_bodies(): walls as the solver builds them

namespace isopound::pre {
namespace {

constexpr double kLevelTolerance2D = 1e-3;  // m: pounding2d.cpp pairs levels within 1 mm
constexpr double kGround = 0.01;            // m: levels below are at the ground

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string metres(double v) {
  return fmt("%.3f m", std::abs(v) < 5e-4 ? 0.0 : v);  // no "-0.000 m"
}

ConvexPolygon polygon(const std::vector<Vec2>& v) {
  return ConvexPolygon(std::span<const Vec2>(v.data(), v.size()));
}

// The node to blame for a structure's placement: `adjacent`, `position`, else its item.
std::pair<InputNode, std::string> placement_node(const StructureMarks& m) {
  if (m.adjacent) return {*m.adjacent, ""};
  if (const auto p = m.item->find("position")) return {*p, ""};
  return {*m.item, "position"};
}

Vec2 closest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return a + t * d;
}

// Buildings placed by `adjacent: {to, side, gap}` (which places bounding boxes): the smallest
// clearance between floors of the two at equal levels, where they pound, must be the declared
// gap; every clearance of the pair is shown with it.
void check_adjacency(const ModelConfig& config, const std::vector<StructureMarks>& marks,
                     const CheckLimits& limits, std::vector<Clearance>& clearances,
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

}  // namespace

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

std::vector<Clearance> check_site(const ScannedModel& model, const Site& site,
                                  const std::vector<StructureProperties>& properties,
                                  const CheckLimits& limits, ProblemList& problems) {
  const ModelConfig& config = *model.config;
  const auto& marks = model.structures;
  const std::size_t n = config.structures3d.size();
  std::vector<Clearance> clearances;

  // Structures overlapping at rest, and the nearest approach of every pair (any levels).
  std::vector<std::vector<double>> nearest(n, std::vector<double>(n, 1e300));
  for (std::size_t i = 0; i < site.slabs.size(); ++i)
    for (std::size_t j = i + 1; j < site.slabs.size(); ++j) {
      const PlanSlab& a = site.slabs[i];
      const PlanSlab& b = site.slabs[j];
      if (a.structure == b.structure) continue;
      const ConvexPolygon pa = polygon(a.plan_W), pb = polygon(b.plan_W);
      const Separation sep = separation_of(pa, pb);
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
          const Separation sep = separation_of(polygon(a.plan_W), polygon(b.plan_W));
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
          const ConvexPolygon pa = polygon(a.plan_W), pb = polygon(b.plan_W);
          const Overlap o = overlap_of(pa, pb);
          if (o.area > area) {
            area = o.area;
            depth = -separation_of(pa, pb).distance;
            where = a.level + " of '" + a.name + "' and " + b.level + " of '" + b.name + "'";
          }
        }
      if (area > 1e-9) {
        const auto [node, key] = placement_node(marks[j]);
        problems.error_at(node, key,
                          "structures '" + config.structures3d[i].name + "' and '" +
                              config.structures3d[j].name + "' overlap at rest: " + where +
                              " share " + fmt("%.3f m2", area) + " (" + metres(depth) + " deep)");
      }
    }

  // Walls: the clearance to the base slab they surround, measured per side against the declared
  // gap; no wall may stand in another structure's slab (up to its height) or on its columns.
  for (const PlanWall& w : site.walls) {
    const StructureMarks& m = marks.at(static_cast<std::size_t>(w.building));
    const InputNode& where = m.walls ? *m.walls : *m.item;
    for (const PlanSlab& s : site.slabs) {
      if (s.structure == w.building && s.level == "base") {
        const Separation sep = separation_of(polygon(s.plan_W), polygon(w.plan_W));
        Clearance c;
        c.a = s.name + "/base";
        c.b = w.name;
        c.structure_a = c.structure_b = w.building;
        c.side = w.side;
        c.measured = sep.distance;
        c.declared = w.declared_gap;
        if (sep.distance > 0) closest_points(s.plan_W, w.plan_W, c.p_WA, c.p_WB);
        clearances.push_back(c);
        if (std::abs(sep.distance - w.declared_gap) > limits.gap_tolerance)
          problems.error_at(where, "gap",
                            "the " + w.side + " wall of '" + w.structure + "' stands " +
                                metres(sep.distance) + " from its base slab (measured), not at " +
                                "the declared gap of " + metres(w.declared_gap));
      } else if (s.structure != w.building && s.elevation <= w.height + limits.level_tolerance) {
        const Overlap o = overlap_of(polygon(s.plan_W), polygon(w.plan_W));
        if (o.area > 1e-9)
          problems.error_at(where, "",
                            "the " + w.side + " wall of '" + w.structure + "' overlaps " + s.level +
                                " of '" + s.name + "' at rest (" + fmt("%.3f m2", o.area) + ")");
      }
    }
    for (std::size_t k = 0; k < site.ground_columns.size(); ++k) {
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
        const StructureMarks& m = marks[i];
        const int storey = a.level_index - (config.structures3d[i].isolated ? 1 : 0);
        const InputNode& where =
            storey >= 0 && storey < static_cast<int>(m.storey.size()) ? m.storey[storey] : *m.item;
        problems.error_at(where, "",
                          a.level + " of '" + a.name + "' at " + metres(a.elevation) +
                              " has no floor of '" + partner->name + "' at its level (nearest: " +
                              partner->level + " at " + metres(partner->elevation) + "), " +
                              (nearest[i][j] > 0 ? metres(nearest[i][j]) + " away"
                                                 : std::string("overlapping it")) +
                              ": it would pound that building's columns, which the model "
                              "does not represent (floors of pounding pairs must be at equal "
                              "levels)");
      }
    }

  // Per structure: stiffness jumps, eccentric mass, bearings.
  for (std::size_t i = 0; i < n; ++i) {
    const Building3DConfig& b = config.structures3d[i];
    const StructureProperties& p = properties[i];
    const StructureMarks& m = marks[i];
    const auto storey_node = [&](int storey) -> const InputNode& {
      if (storey >= 1 && storey <= static_cast<int>(m.storey.size())) return m.storey[storey - 1];
      return *m.item;
    };
    for (std::size_t s = 0; s + 1 < p.storeys.size(); ++s) {
      const StoreyProperties& lo = p.storeys[s];
      const StoreyProperties& hi = p.storeys[s + 1];
      if (lo.storey == 0) continue;  // the isolation layer is meant to be soft
      for (const auto& [axis, k_lo, k_hi] :
           {std::tuple{"x", lo.k_x, hi.k_x}, std::tuple{"y", lo.k_y, hi.k_y}}) {
        const double ratio = std::max(k_lo / k_hi, k_hi / k_lo);
        if (ratio > limits.stiffness_jump) {
          problems.warning_at(storey_node(hi.storey), "",
                              "storey stiffness jumps " + fmt("%.1f", ratio) + "x along " + axis +
                                  " from " + lo.label + " (" + fmt("%.4g", k_lo / 1e6) +
                                  " MN/m) to " + hi.label + " (" + fmt("%.4g", k_hi / 1e6) +
                                  " MN/m): more than " + fmt("%g", limits.stiffness_jump) +
                                  "x (a soft or stiff storey?)");
          break;
        }
      }
    }
    for (const StoreyProperties& s : p.storeys) {
      const bool ex = std::abs(s.eccentricity.x) > limits.eccentricity_ratio * s.r_x;
      const bool ey = std::abs(s.eccentricity.y) > limits.eccentricity_ratio * s.r_y;
      if (!ex && !ey) continue;
      const InputNode& where = s.storey == 0 ? (m.base ? *m.base : *m.item) : storey_node(s.storey);
      problems.warning_at(where, "",
                          "very eccentric mass in " + s.label + " of '" + b.name + "': e = (" +
                              metres(s.eccentricity.x) + ", " + metres(s.eccentricity.y) +
                              ") between the centres of mass and stiffness, more than " +
                              fmt("%.2f", limits.eccentricity_ratio) +
                              " of the torsional radii (r_x " + metres(s.r_x) + ", r_y " +
                              metres(s.r_y) + ") (EC8 4.2.3.2(6))");
    }
    if (b.isolated && !site.slabs.empty()) {
      std::vector<Vec2> bearings;
      for (const PlanSlab& slab : site.slabs)
        if (slab.structure == static_cast<int>(i) && slab.level == "base")
          for (const PlanBearing& br : slab.bearings) bearings.push_back(br.p_W);
      const InputNode& where = m.bearings ? *m.bearings : (m.base ? *m.base : *m.item);
      if (bearings.size() < 3) {
        problems.warning_at(where, "",
                            "only " + std::to_string(bearings.size()) + " bearing" +
                                (bearings.size() == 1 ? "" : "s") + " under '" + b.name +
                                "': fewer than 3 cannot resist torsion stably");
      } else {
        // Collinear: every bearing within 1e-6 of the slab's size of the line through the two
        // farthest apart.
        std::size_t ia = 0, ib = 1;
        double far = -1;
        for (std::size_t u = 0; u < bearings.size(); ++u)
          for (std::size_t v = u + 1; v < bearings.size(); ++v) {
            const Vec2 d = bearings[v] - bearings[u];
            if (dot(d, d) > far) far = dot(d, d), ia = u, ib = v;
          }
        const Vec2 d = bearings[ib] - bearings[ia];
        const double len = std::sqrt(far);
        bool collinear = len > 0;
        for (Vec2 q : bearings)
          if (std::abs(cross(d, q - bearings[ia])) / len > 1e-6 * len) collinear = false;
        if (collinear || len == 0)
          problems.warning_at(where, "",
                              "the bearings under '" + b.name +
                                  "' stand on one line (fewer than 3 positions not collinear): "
                                  "torsion is resisted only by their spread along it");
      }
    }
  }
  return clearances;
}

void check_model2d(const ScannedModel& model, const CheckLimits& limits, ProblemList& problems) {
  const ModelConfig& config = *model.config;
  // Stiffness jumps of the main building's storeys.
  const BuildingConfig& b = config.building;
  for (std::size_t s = 0; s + 1 < b.floors.size(); ++s) {
    const double k_lo = b.floors[s].stiffness, k_hi = b.floors[s + 1].stiffness;
    const double ratio = std::max(k_lo / k_hi, k_hi / k_lo);
    if (ratio <= limits.stiffness_jump || !model.floors) continue;
    // A copy: elements() is a temporary vector.
    const InputNode where =
        model.floors->is_sequence() ? model.floors->elements()[s + 1] : *model.floors;
    problems.warning_at(where, "",
                        "storey stiffness jumps " + fmt("%.1f", ratio) + "x from storey " +
                            std::to_string(s + 1) + " (" + fmt("%.4g", k_lo / 1e6) +
                            " MN/m) to storey " + std::to_string(s + 2) + " (" +
                            fmt("%.4g", k_hi / 1e6) + " MN/m): more than " +
                            fmt("%g", limits.stiffness_jump) + "x (a soft or stiff storey?)");
  }
  // Neighbours: every level of one within the other's height needs a partner (pounding2d.cpp
  // pairs levels within 1 mm).
  const auto elevations = [](const BuildingConfig& x) {
    std::vector<double> z;
    double e = 0.0;
    for (const FloorConfig& f : x.floors) z.push_back(e += f.height);
    return z;
  };
  const std::vector<double> z_main = elevations(b);
  for (std::size_t k = 0; k < config.neighbours.size() && k < model.neighbours.size(); ++k) {
    const BuildingConfig& nb = config.neighbours[k].building;
    const std::vector<double> z_other = elevations(nb);
    for (int pass = 0; pass < 2; ++pass) {
      const std::vector<double>& za = pass == 0 ? z_main : z_other;
      const std::vector<double>& zb = pass == 0 ? z_other : z_main;
      const std::string& na = pass == 0 ? b.name : nb.name;
      const std::string& nbn = pass == 0 ? nb.name : b.name;
      for (std::size_t f = 0; f < za.size(); ++f) {
        if (za[f] > zb.back() + kLevelTolerance2D) continue;
        double dz = 1e300, nearest = 0;
        for (double z : zb)
          if (std::abs(z - za[f]) < dz) dz = std::abs(z - za[f]), nearest = z;
        if (dz <= kLevelTolerance2D) continue;
        problems.error_at(model.neighbours[k], "",
                          "floor " + std::to_string(f + 1) + " of '" + na + "' at " +
                              metres(za[f]) + " has no floor of '" + nbn +
                              "' at its level (nearest " + metres(nearest) +
                              "): it would pound that building's columns, which the model does "
                              "not represent (floors of pounding pairs must be at equal levels)");
      }
    }
  }
}

}  // namespace isopound::pre
