// Gmsh models of the site: built with the built-in (geo) kernel, meshed in 2D, written with
// gmsh::write. Gmsh throws std::string (DEPENDENCIES.md): turned into std::runtime_error here.
#include "geometry/pre/gmsh_files.h"
#include "geometry/plan_shape.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <tuple>

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

// The points and lines of one model: a point at the position of an earlier one is that point, a
// line between two points already joined is that line (reversed if need be), so that bodies that
// touch (a column flush with a slab's corner) share mesh nodes instead of duplicating them
// (gmsh -check fails on duplicate nodes). Positions are compared to the micrometre.
struct Geometry {
  std::map<std::tuple<long long, long long, long long>, int> points;
  std::map<std::pair<int, int>, int> lines;

  int point(double x, double y, double z, double size) {
    const auto key =
        std::make_tuple(std::llround(x * 1e6), std::llround(y * 1e6), std::llround(z * 1e6));
    const auto it = points.find(key);
    if (it != points.end()) return it->second;
    return points[key] = gmsh::model::geo::addPoint(x, y, z, size);
  }
  int line(int from, int to) {
    if (const auto it = lines.find({from, to}); it != lines.end()) return it->second;
    if (const auto it = lines.find({to, from}); it != lines.end()) return -it->second;
    return lines[{from, to}] = gmsh::model::geo::addLine(from, to);
  }
  // A plane surface bounded by the closed chain of points.
  int surface(const std::vector<int>& chain) {
    std::vector<int> loop;
    for (std::size_t i = 0; i < chain.size(); ++i)
      loop.push_back(line(chain[i], chain[(i + 1) % chain.size()]));
    return gmsh::model::geo::addPlaneSurface({gmsh::model::geo::addCurveLoop(loop)});
  }
  // A plane surface through the polygon at height z; returns its tag.
  int polygon(const std::vector<Vec2>& plan, double z, double size) {
    std::vector<int> chain;
    for (Vec2 p : plan) chain.push_back(point(p.x, p.y, z, size));
    return surface(chain);
  }
};

// A slab whose mesh has a node at every given point (the bearings): a point on a vertex is that
// vertex, one on an edge splits the edge there, one inside is embedded in the surface (after
// synchronize: embed()). Without this the points are free nodes on top of the slab's own (gmsh
// -check: duplicate nodes).
struct SlabWithPoints {
  int surface = 0;
  std::vector<int> point_tags;  // per given point
  std::vector<int> inside;      // to embed
  void embed() const {
    if (!inside.empty()) gmsh::model::mesh::embed(0, inside, 2, surface);
  }
};

SlabWithPoints add_slab(Geometry& geometry, const std::vector<Vec2>& plan, double z, double size,
                        const std::vector<Vec2>& marks, double mark_size) {
  const double tol = 1e-9 * std::sqrt(plan_area_properties(plan).area);
  SlabWithPoints slab;
  slab.point_tags.assign(marks.size(), 0);
  std::vector<int> chain;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const Vec2 a = plan[i], b = plan[(i + 1) % plan.size()], d = b - a;
    const double length = std::sqrt(dot(d, d));
    // The vertex, then the marks on the open edge a -> b in order along it.
    std::vector<std::pair<double, std::size_t>> on_edge;
    bool marked = false;
    for (std::size_t k = 0; k < marks.size(); ++k) {
      const Vec2 q = marks[k] - a;
      const double t = dot(q, d) / length;  // along the edge, m
      if (std::sqrt(dot(q, q)) <= tol)
        marked = true;
      else if (std::abs(cross(d, q)) / length <= tol && t > tol && t < length - tol)
        on_edge.push_back({t, k});
    }
    chain.push_back(geometry.point(a.x, a.y, z, marked ? mark_size : size));
    for (std::size_t k = 0; k < marks.size(); ++k)
      if (std::sqrt(dot(marks[k] - a, marks[k] - a)) <= tol) slab.point_tags[k] = chain.back();
    std::sort(on_edge.begin(), on_edge.end());
    for (const auto& [t, k] : on_edge) {
      slab.point_tags[k] = geometry.point(marks[k].x, marks[k].y, z, mark_size);
      if (slab.point_tags[k] != chain.back()) chain.push_back(slab.point_tags[k]);
    }
  }
  slab.surface = geometry.surface(chain);
  for (std::size_t k = 0; k < marks.size(); ++k)
    if (!slab.point_tags[k]) {
      slab.point_tags[k] = geometry.point(marks[k].x, marks[k].y, z, mark_size);
      slab.inside.push_back(slab.point_tags[k]);
    }
  return slab;
}

double slab_size(const std::vector<Vec2>& plan) {
  return std::sqrt(plan_area_properties(plan).area) / 6.0;
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

void add_columns(Geometry& geometry, const std::vector<PlanColumn>& columns,
                 const std::string& prefix, double z, Groups& groups) {
  for (const PlanColumn& c : columns)
    groups.add(prefix + "/column", 2, geometry.polygon(c.outline_W(), z, 0.5 * std::min(c.b, c.h)));
}

// One model: the levels whose elevation passes `keep`.
template <typename Keep>
GmshFile write_model(const Site& site, const std::string& dir, const std::string& stem,
                     double elevation, Keep keep) {
  gmsh::model::add(stem);
  Groups groups;
  Geometry geometry;
  std::vector<SlabWithPoints> slabs;
  for (const PlanSlab& s : site.slabs) {
    if (!keep(s.elevation)) continue;
    const std::string prefix = s.name + "/" + s.level;
    std::vector<Vec2> bearings;
    for (const PlanBearing& b : s.bearings) bearings.push_back(b.p_W);
    slabs.push_back(add_slab(geometry, s.plan_W, s.elevation, slab_size(s.plan_W), bearings, 0.5));
    groups.add(prefix + "/slab", 2, slabs.back().surface);
    add_columns(geometry, s.columns, prefix, s.elevation, groups);
    for (int tag : slabs.back().point_tags) groups.add(prefix + "/bearing", 0, tag);
  }
  if (keep(0.0)) {
    for (std::size_t i = 0; i < site.ground_columns.size(); ++i) {
      std::string name;
      for (const PlanSlab& s : site.slabs)
        if (s.structure == site.ground_columns_structure[i]) name = s.name;
      add_columns(geometry, {site.ground_columns[i]}, name + "/ground", 0.0, groups);
    }
  }
  // Walls at the level they face (the base slab's, at the ground unless isolated above a storey).
  for (const PlanWall& w : site.walls)
    if (keep(w.elevation))
      groups.add(w.structure + "/base/wall", 2,
                 geometry.polygon(w.plan_W, w.elevation, slab_size(w.plan_W)));
  gmsh::model::geo::synchronize();
  for (const SlabWithPoints& slab : slabs) slab.embed();
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
    if (!site.ground_columns.empty()) levels.emplace(0L, 0.0);
    for (const PlanWall& w : site.walls)
      levels.emplace(std::lround(w.elevation * 100), w.elevation);
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
    Geometry geometry;
    const int surface = geometry.polygon(plan, 0.0, size);
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
