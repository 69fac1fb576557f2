// Section and stiffness properties from the solver's own matrices: storey_stiffness() and
// diaphragm_mass() of building3d.h, linear_model3d() for the bearings, so what is printed is what
// the analysis uses.
#include "geometry/pre/properties.h"
#include "geometry/plan_shape.h"

#include <cmath>
#include <cstdio>
#include <span>

#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"
#include "solver/structures/levels3d.h"

namespace isopound::pre {
namespace {

// Centre of mass and radius of gyration about it of a sum of 3 x 3 diaphragm mass matrices.
void mass_centre(const Eigen::Matrix3d& m, Vec2& p_WM, double& l_s) {
  // M = T^T diag(m, m, J) T with T = [[1, 0, -y], [0, 1, x], [0, 0, 1]]: M(0, 2) = -m y,
  // M(1, 2) = m x, M(2, 2) = J + m (x^2 + y^2).
  const double mass = m(0, 0);
  p_WM = {m(1, 2) / mass, -m(0, 2) / mass};
  const double j = m(2, 2) - mass * dot(p_WM, p_WM);
  l_s = std::sqrt(std::max(0.0, j / mass));
}

StoreyProperties storey_properties(const Eigen::Matrix3d& k, const Eigen::Matrix3d& m) {
  StoreyProperties s;
  centre_of_stiffness(k, s.p_WS, s.k_theta);
  s.k_x = k(0, 0);
  s.k_y = k(1, 1);
  mass_centre(m, s.p_WM, s.l_s);
  s.eccentricity = s.p_WM - s.p_WS;
  s.r_x = std::sqrt(s.k_theta / s.k_y);
  s.r_y = std::sqrt(s.k_theta / s.k_x);
  return s;
}

// Round-off (|v| < 1 nm) printed as 0, not -0.000.
double c0(double v) {
  return std::abs(v) < 1e-9 ? 0.0 : v;
}

nlohmann::ordered_json point(Vec2 p) {
  return nlohmann::ordered_json::array({c0(p.x), c0(p.y)});
}

}  // namespace

void centre_of_stiffness(const Eigen::Matrix3d& k, Vec2& p_WS, double& k_theta_S) {
  // Moving the DOF point to S: q = A q_S, A = [[1, 0, y_S], [0, 1, -x_S], [0, 0, 1]];
  // (A^T k A)(0, 2) = k_ut + k_uu y_S - k_uv x_S = 0 and (A^T k A)(1, 2) = k_vt + k_uv y_S -
  // k_vv x_S = 0.
  Eigen::Matrix2d a;
  a << -k(0, 1), k(0, 0), -k(1, 1), k(0, 1);
  const Eigen::Vector2d s = a.partialPivLu().solve(Eigen::Vector2d(-k(0, 2), -k(1, 2)));
  p_WS = {s[0], s[1]};
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  A(0, 2) = p_WS.y;
  A(1, 2) = -p_WS.x;
  k_theta_S = (A.transpose() * k * A)(2, 2);
}

std::vector<StructureProperties> structure_properties(const ModelConfig& config) {
  std::vector<StructureProperties> out;
  for (const Building3DConfig& b : config.structures3d) {
    StructureProperties p;
    p.name = b.name;
    p.isolated = b.isolated;
    // Levels in elevation order (levels3d.h): the base slab over floor k when isolated above a
    // storey.
    const std::vector<Level3D> levels_B = levels3d(b);
    std::vector<Diaphragm3DConfig> levels;
    for (const Level3D& level : levels_B) levels.push_back(diaphragm_in_plan(b, *level.diaphragm));
    std::vector<Eigen::Matrix3d> masses;
    for (std::size_t l = 0; l < levels.size(); ++l) {
      DiaphragmProperties d;
      d.level = levels_B[l].name;
      d.elevation = levels_B[l].elevation;
      d.mass = levels[l].mass;
      d.exact = plan_area_properties(levels[l].plan);
      d.radius_of_gyration = std::sqrt(d.exact.radius_of_gyration_sq());
      masses.push_back(diaphragm_mass(levels[l], b.polar_moment_rule));
      mass_centre(masses.back(), d.p_WM, d.mass_radius_of_gyration);
      p.diaphragms.push_back(d);
    }
    const auto storey_k = [&](std::size_t s) {
      return storey_stiffness(columns_in_plan(b, b.storeys[s].columns), b.storeys[s].height,
                              b.column_coupling);
    };
    StoreyProperties isolation;
    if (b.isolated) {
      // Bearings at K_post: the base slab's block of the isolated linear model less the columns
      // of the storey standing on it (storey k + 1).
      const int base = base_level3d(b);
      const LinearModel3D lin = linear_model3d(b, false, false);
      const Eigen::Matrix3d k =
          lin.stiffness.block<3, 3>(3 * base, 3 * base) - storey_k(static_cast<std::size_t>(base));
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (std::size_t l = static_cast<std::size_t>(base); l < masses.size(); ++l) m += masses[l];
      isolation = storey_properties(k, m);
      isolation.storey = 0;
      isolation.label = "isolation";
    }
    for (std::size_t s = 0; s < b.storeys.size(); ++s) {
      // The isolation layer in its place: between storey k and storey k + 1.
      if (b.isolated && s == static_cast<std::size_t>(b.isolation_level))
        p.storeys.push_back(isolation);
      const int floor = static_cast<int>(s) + 1;
      StoreyProperties sp =
          storey_properties(storey_k(s), masses[static_cast<std::size_t>(floor_level3d(b, floor))]);
      sp.storey = floor;
      sp.label = "storey " + std::to_string(floor);
      p.storeys.push_back(sp);
    }
    out.push_back(p);
  }
  return out;
}

nlohmann::ordered_json properties_json(const std::vector<StructureProperties>& all) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const StructureProperties& p : all) {
    nlohmann::ordered_json s;
    s["name"] = p.name;
    s["isolated"] = p.isolated;
    s["frame"] = "model plan frame W, SI units (m, kg, N)";
    for (const DiaphragmProperties& d : p.diaphragms) {
      nlohmann::ordered_json j;
      j["level"] = d.level;
      j["elevation_m"] = d.elevation;
      j["mass_kg"] = d.mass;
      j["area_m2"] = d.exact.area;
      j["centroid_m"] = point(d.exact.p_WC);
      j["polar_moment_m4"] = d.exact.polar_moment_c;
      j["polar_radius_of_gyration_m"] = d.radius_of_gyration;
      j["centre_of_mass_m"] = point(d.p_WM);
      j["mass_radius_of_gyration_m"] = d.mass_radius_of_gyration;
      if (d.meshed) {
        j["mesh"] = {{"triangles", d.triangles},
                     {"area_m2", d.mesh.area},
                     {"centroid_m", point(d.mesh.p_WC)},
                     {"polar_moment_m4", d.mesh.polar_moment_c},
                     {"max_relative_difference", d.relative_difference}};
      }
      s["diaphragms"].push_back(j);
    }
    for (const StoreyProperties& st : p.storeys) {
      nlohmann::ordered_json j;
      j["storey"] = st.label;
      j["stiffness_x_N_per_m"] = st.k_x;
      j["stiffness_y_N_per_m"] = st.k_y;
      j["torsional_stiffness_Nm_per_rad"] = st.k_theta;
      j["centre_of_stiffness_m"] = point(st.p_WS);
      j["centre_of_mass_m"] = point(st.p_WM);
      j["eccentricity_m"] = point(st.eccentricity);
      j["torsional_radius_x_m"] = st.r_x;
      j["torsional_radius_y_m"] = st.r_y;
      j["mass_radius_of_gyration_m"] = st.l_s;
      s["storeys"].push_back(j);
    }
    out.push_back(s);
  }
  return out;
}

std::string properties_text(const std::vector<StructureProperties>& all) {
  std::string out;
  char line[400];
  for (const StructureProperties& p : all) {
    out += "Structure '" + p.name + "' (plan frame W, m)\n";
    out +=
        "  level      area [m2]  centroid x, y        r_g [m]  mass [t]  centre of mass x, y  "
        "mesh vs polygon\n";
    for (const DiaphragmProperties& d : p.diaphragms) {
      std::string mesh = "-";
      if (d.meshed) {
        std::snprintf(line, sizeof line, "%.1e (%d triangles)", d.relative_difference, d.triangles);
        mesh = line;
      }
      std::snprintf(line, sizeof line, "  %-9s %10.3f  %8.3f %8.3f  %9.3f %9.1f  %8.3f %8.3f  %s\n",
                    d.level.c_str(), d.exact.area, c0(d.exact.p_WC.x), c0(d.exact.p_WC.y),
                    d.radius_of_gyration, d.mass / 1e3, c0(d.p_WM.x), c0(d.p_WM.y), mesh.c_str());
      out += line;
    }
    out +=
        "  storey      K_x [MN/m]  K_y [MN/m]  centre of stiffness  centre of mass      "
        "e_x [m]  e_y [m]  r_x [m]  r_y [m]  l_s [m]\n";
    for (const StoreyProperties& s : p.storeys) {
      std::snprintf(line, sizeof line,
                    "  %-10s %11.2f %11.2f  %8.3f %8.3f   %8.3f %8.3f  %7.3f  %7.3f  %7.3f  %7.3f  "
                    "%7.3f\n",
                    s.label.c_str(), s.k_x / 1e6, s.k_y / 1e6, c0(s.p_WS.x), c0(s.p_WS.y),
                    c0(s.p_WM.x), c0(s.p_WM.y), c0(s.eccentricity.x), c0(s.eccentricity.y), s.r_x,
                    s.r_y, s.l_s);
      out += line;
    }
  }
  return out;
}

}  // namespace isopound::pre
