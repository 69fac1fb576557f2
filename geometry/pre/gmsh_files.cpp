// Gmsh models of the site: built with the built-in (geo) kernel, meshed in 2D, written with
// gmsh::write. Gmsh throws std::string (DEPENDENCIES.md): turned into std::runtime_error here.
#include "geometry/pre/gmsh_files.h"

#include <gmsh.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace isopound::pre {
namespace {

namespace fs = std::filesystem;

template <typename F>
auto gmsh_call(F f) {
  try {
    return f();
  } catch (const std::string& e) {
    throw std::runtime_error("Gmsh: " + e);
  }
}

// A plane surface through the polygon at height z; returns its tag.
int add_polygon(const std::vector<Vec2>& plan, double z, double size) {
  std::vector<int> points, lines;
  for (Vec2 p : plan) points.push_back(gmsh::model::geo::addPoint(p.x, p.y, z, size));
  for (std::size_t i = 0; i < points.size(); ++i)
    lines.push_back(gmsh::model::geo::addLine(points[i], points[(i + 1) % points.size()]));
  const int loop = gmsh::model::geo::addCurveLoop(lines);
  return gmsh::model::geo::addPlaneSurface({loop});
}

double slab_size(const std::vector<Vec2>& plan) {
  return std::sqrt(area_properties(ConvexPolygon(std::span<const Vec2>(plan))).area) / 6.0;
}

// Collects entities per physical group name, then creates the groups.
struct Groups {
  std::map<std::string, std::pair<int, std::vector<int>>> by_name;  // name -> (dim, tags)
  void add(const std::string& name, int dim, int tag) {
    auto& g = by_name[name];
    g.first = dim;
    g.second.push_back(tag);
  }
  std::vector<std::string> create() {
    std::vector<std::string> names;
    for (const auto& [name, g] : by_name) {
      const int tag = gmsh::model::addPhysicalGroup(g.first, g.second);
      gmsh::model::setPhysicalName(g.first, tag, name);
      names.push_back(name);
    }
    return names;
  }
};

void add_columns(const std::vector<PlanColumn>& columns, const std::string& prefix, double z,
                 Groups& groups) {
  for (const PlanColumn& c : columns)
    groups.add(prefix + "/column", 2, add_polygon(c.outline_W(), z, 0.5 * std::min(c.b, c.h)));
}

// One model: the levels whose elevation passes `keep`.
template <typename Keep>
GmshFile write_model(const Site& site, const std::string& dir, const std::string& stem,
                     double elevation, Keep keep) {
  gmsh::model::add(stem);
  Groups groups;
  for (const PlanSlab& s : site.slabs) {
    if (!keep(s.elevation)) continue;
    const std::string prefix = s.name + "/" + s.level;
    groups.add(prefix + "/slab", 2, add_polygon(s.plan_W, s.elevation, slab_size(s.plan_W)));
    add_columns(s.columns, prefix, s.elevation, groups);
    for (const PlanBearing& b : s.bearings)
      groups.add(prefix + "/bearing", 0,
                 gmsh::model::geo::addPoint(b.p_W.x, b.p_W.y, s.elevation, 0.5));
  }
  if (keep(0.0)) {
    for (std::size_t i = 0; i < site.ground_columns.size(); ++i) {
      std::string name;
      for (const PlanSlab& s : site.slabs)
        if (s.structure == site.ground_columns_structure[i]) name = s.name;
      add_columns({site.ground_columns[i]}, name + "/ground", 0.0, groups);
    }
    for (const PlanWall& w : site.walls)
      groups.add(w.structure + "/base/wall", 2, add_polygon(w.plan_W, 0.0, slab_size(w.plan_W)));
  }
  gmsh::model::geo::synchronize();
  GmshFile file{stem, elevation, groups.create()};
  gmsh::model::mesh::generate(2);
  gmsh::write((fs::path(dir) / (stem + ".geo_unrolled")).string());
  gmsh::write((fs::path(dir) / (stem + ".msh")).string());
  gmsh::model::remove();
  return file;
}

}  // namespace

GmshSession::GmshSession() {
  gmsh_call([] {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
  });
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {
  }
}

std::vector<GmshFile> write_gmsh_files(const Site& site, const std::string& dir) {
  return gmsh_call([&] {
    // Distinct levels, to the centimetre (the solver pairs floors within 1 cm).
    std::map<long, double> levels;
    for (const PlanSlab& s : site.slabs)
      levels.emplace(std::lround(s.elevation * 100), s.elevation);
    if (!site.ground_columns.empty() || !site.walls.empty()) levels.emplace(0L, 0.0);
    std::vector<GmshFile> files;
    for (const auto& [cm, z] : levels) {
      char stem[64];
      std::snprintf(stem, sizeof stem, "level-z%.2fm", cm / 100.0);
      files.push_back(write_model(site, dir, stem, z,
                                  [cm = cm](double e) { return std::lround(e * 100) == cm; }));
    }
    files.push_back(write_model(site, dir, "site", -1.0, [](double) { return true; }));
    return files;
  });
}

AreaProperties mesh_area_properties(const std::vector<Vec2>& plan, double size, int& triangles) {
  return gmsh_call([&] {
    gmsh::model::add("area-check");
    const int surface = add_polygon(plan, 0.0, size);
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(2);
    const int type = gmsh::model::mesh::getElementType("Triangle", 1);
    std::vector<double> local, weights, jac, det, coord;
    gmsh::model::mesh::getIntegrationPoints(type, "Gauss2", local, weights);
    gmsh::model::mesh::getJacobians(type, local, jac, det, coord, surface);
    // About the vertex mean (less round-off far from the origin); Gauss2 integrates the
    // quadratic |p|^2 exactly on straight triangles.
    Vec2 o;
    for (Vec2 p : plan) o = o + (1.0 / plan.size()) * p;
    const std::size_t g = weights.size();
    double a = 0, sx = 0, sy = 0, sxx = 0;
    for (std::size_t k = 0; k < det.size(); ++k) {
      const double w = weights[k % g] * std::abs(det[k]);
      const double x = coord[3 * k] - o.x, y = coord[3 * k + 1] - o.y;
      a += w;
      sx += w * x;
      sy += w * y;
      sxx += w * (x * x + y * y);
    }
    triangles = static_cast<int>(det.size() / g);
    gmsh::model::remove();
    AreaProperties p;
    p.area = a;
    p.p_WC = o + Vec2{sx / a, sy / a};
    p.polar_moment_c = sxx - (sx * sx + sy * sy) / a;
    return p;
  });
}

}  // namespace isopound::pre
