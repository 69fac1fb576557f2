// isopound-pre's warnings (see checks.h). Each blames the key it concerns.
#include "geometry/pre/checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "solver/structures/config3d.h"

namespace isopound::pre {
namespace {

std::string fmt(const char* f, double v) {
  return format_number(f, v);
}
std::string metres(double v) {
  return metres_text(v);
}

}  // namespace

void check_structures(const ScannedModel& model, const Site& site,
                      const std::vector<StructureProperties>& properties, const CheckLimits& limits,
                      ProblemList& problems) {
  const ModelConfig& config = *model.config;
  const auto& marks = model.structures;
  const std::size_t n = std::min(config.structures3d.size(), marks.size());
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
      // The isolation layer (first, or between storeys k and k + 1) is meant to be soft.
      if (lo.storey == 0 || hi.storey == 0) continue;
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
}

void check_model2d(const ScannedModel& model, const CheckLimits& limits, ProblemList& problems) {
  const ModelConfig& config = *model.config;
  // Stiffness jumps of the main building's storeys.
  const BuildingConfig& b = config.building;
  for (std::size_t s = 0; s + 1 < b.floors.size(); ++s) {
    // Storeys k and k+1 of a building isolated on floor k are not neighbours: the isolation
    // layer stands between them (docs/isolation-level.md).
    if (b.isolated && b.isolation_level > 0 && s + 1 == static_cast<std::size_t>(b.isolation_level))
      continue;
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
}

}  // namespace isopound::pre
