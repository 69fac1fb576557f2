// Struck columns in 3D: the site search (slab vs storey between its floors, section within reach)
// and the elements, each column's lateral stiffness moved from the storey into its element.
#include "solver/structures/struck_columns3d.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/overlap.h"
#include "geometry/plan_overlap.h"
#include "solver/elements/struck_column3d.h"
#include "solver/structures/building3d.h"
#include "solver/structures/column_element.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"
#include "solver/structures/site_plan.h"

namespace isopound {

namespace {

// The column's section as site_plan.h draws it, in the plan frame.
std::vector<Vec2> section_of(const Column3DConfig& c_W) {
  PlanColumn p;
  p.p_W = c_W.position;
  p.orientation = c_W.orientation;
  column_rectangle(c_W.I11, c_W.I22, p.b, p.h);
  return p.outline_W();
}

}  // namespace

std::string StruckColumnSite::label() const {
  return striker_name + "/" + slab_level + " on " + struck_name + " story " +
         std::to_string(storey) + " column " + column_label;
}

int storey_between_floors(const Building3DConfig& b, double z, double tolerance) {
  const std::vector<Level3D> levels = levels3d(b);
  for (int k = 1; k <= static_cast<int>(b.storeys.size()); ++k) {
    const int lower = storey_lower_level3d(b, k);
    const double z_lo = lower >= 0 ? levels[static_cast<std::size_t>(lower)].elevation : 0.0;
    const double z_hi = levels[static_cast<std::size_t>(floor_level3d(b, k))].elevation;
    if (z > z_lo + tolerance && z < z_hi - tolerance) return k;
  }
  return 0;
}

std::vector<StruckColumnSite> struck_column_sites(const ModelConfig& config) {
  std::vector<StruckColumnSite> out;
  const double tol = config.contact3d.elevation_tolerance;
  for (const SiteBody& slab : site_bodies(config)) {
    if (slab.role != "slab") continue;
    for (std::size_t o = 0; o < config.structures3d.size(); ++o) {
      if (static_cast<int>(o) == slab.building) continue;
      const Building3DConfig& b = config.structures3d[o];
      const int k = storey_between_floors(b, slab.elevation, tol);
      if (k == 0) continue;
      const std::vector<Level3D> levels = levels3d(b);
      const int lower = storey_lower_level3d(b, k);
      const double z_lo = lower >= 0 ? levels[static_cast<std::size_t>(lower)].elevation : 0.0;
      const double z_hi = levels[static_cast<std::size_t>(floor_level3d(b, k))].elevation;
      const std::vector<Column3DConfig> columns =
          columns_in_plan(b, b.storeys[static_cast<std::size_t>(k) - 1].columns);
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const std::vector<Vec2> section = section_of(columns[c]);
        const Separation sep =
            slab.convex()
                ? separation_of(slab.plan_W, ConvexPolygon(std::span<const Vec2>(section.data(),
                                                                                 section.size())))
                : plan_separation(slab.outline(), SimplePolygon(std::span<const Vec2>(section)));
        if (sep.distance > config.contact3d.search_distance) continue;
        StruckColumnSite s;
        s.striker = slab.building;
        s.struck = static_cast<int>(o);
        s.striker_name = slab.structure;
        s.struck_name = b.name;
        s.slab_level = slab.level;
        s.slab_elevation = slab.elevation;
        s.storey = k;
        s.z_lower = z_lo;
        s.z_upper = z_hi;
        s.column = static_cast<int>(c);
        s.column_label = columns[c].label;
        s.section_W = section;
        s.separation = sep.distance;
        out.push_back(std::move(s));
      }
    }
  }
  return out;
}

void add_struck_columns3d(Model& model, const ModelConfig& config) {
  if (!config.contact3d.pounding) return;
  for (const StruckColumnSite& site : struck_column_sites(config)) {
    const Building3DConfig& striker = config.structures3d[static_cast<std::size_t>(site.striker)];
    const Building3DConfig& b = config.structures3d[static_cast<std::size_t>(site.struck)];
    const StruckColumns3DConfig& sc = b.struck_columns;
    if (!sc.given) continue;  // refused by the site checks
    const Column3DConfig c =
        columns_in_plan(b, b.storeys[static_cast<std::size_t>(site.storey) - 1]
                               .columns)[static_cast<std::size_t>(site.column)];
    if (c.hysteresis.yields())
      throw std::invalid_argument(site.label() + ": a struck column must be elastic");
    const std::vector<Level3D> levels = levels3d(b);
    const int lower = storey_lower_level3d(b, site.storey);
    const int upper = floor_level3d(b, site.storey);
    const auto dofs = [&](const std::string& prefix) {
      return std::array<int, 3>{find_dof(model, prefix + " (x)"), find_dof(model, prefix + " (y)"),
                                find_dof(model, prefix + " (theta)")};
    };
    StruckColumn3DSpec spec;
    const double L = site.z_upper - site.z_lower, a = site.slab_elevation - site.z_lower;
    const double I[2] = {c.I22, c.I11};
    for (int i = 0; i < 2; ++i) {
      HingedColumnSection& s = spec.axis[static_cast<std::size_t>(i)];
      s.E = c.E;
      s.I = I[i];
      s.length = L;
      s.node = a;
      s.yield_moment = sc.yield_moment[static_cast<std::size_t>(i)];
      s.hardening = sc.hardening_ratio * 6.0 * c.E * I[i] / L;
    }
    spec.shear_capacity = sc.shear_check ? sc.shear_capacity : 0.0;
    spec.p_W = c.position;
    spec.orientation = c.orientation;
    spec.slab = dofs(striker.name + "/" + site.slab_level);
    if (lower >= 0) spec.lower = dofs(b.name + "/" + levels[static_cast<std::size_t>(lower)].name);
    spec.upper = dofs(b.name + "/" + levels[static_cast<std::size_t>(upper)].name);
    for (const SiteBody& body : site_bodies(config))
      if (body.building == site.striker && body.role == "slab" && body.level == site.slab_level) {
        spec.slab_plan_W.assign(body.plan_W.vertices().begin(), body.plan_W.vertices().end());
        if (!body.convex())
          spec.slab_outline_W.assign(body.outline_W.vertices().begin(),
                                     body.outline_W.vertices().end());
        spec.slab_mass = body.mass;
      }
    spec.section_W = site.section_W;
    // The floors seen through a point load at a on a column fixed at both ends (the ground
    // takes its reaction: +inf).
    const double bb = L - a, r_lower = bb * bb * (L + 2 * a) / (L * L * L),
                 r_upper = a * a * (L + 2 * bb) / (L * L * L);
    spec.struck_mass = lower >= 0
                           ? r_lower * levels[static_cast<std::size_t>(lower)].diaphragm->mass +
                                 r_upper * levels[static_cast<std::size_t>(upper)].diaphragm->mass
                           : std::numeric_limits<double>::infinity();
    // The column's lateral stiffness and hinges are its ColumnLine's (building3d.cpp, every
    // column of a building with struck_columns:): the struck column takes its place.
    const std::string line = hinged_column_label(b.name, site.storey - 1, c.label);
    int element = -1;
    for (std::size_t e = 0; e < model.elements.size() && element < 0; ++e)
      if (model.elements[e]->label() == line) element = static_cast<int>(e);
    if (element < 0) throw std::logic_error(site.label() + ": no column line " + line);
    for (const int u : {spec.slab[0], spec.lower[0], spec.upper[0]})
      note_upper_contact(model, u, element, false);
    model.elements[static_cast<std::size_t>(element)] = std::make_unique<StruckColumn3D>(
        site.label(), spec, pair_law(config, spec.slab_mass, spec.struck_mass));
  }
}

}  // namespace isopound
