// Centres of stiffness and mass, eccentricity and torsional radius of isopound-pre against hand
// calculations.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "geometry/pre/checks.h"
#include "geometry/pre/model_scan.h"
#include "geometry/pre/properties.h"
#include "pre_test_support.h"
#include "solver/structures/building3d.h"
#include "solver/structures/config3d.h"

namespace isopound::pre::test {
namespace {

std::vector<StructureProperties> properties_of(const std::string& path) {
  ProblemList problems;
  const ScannedModel m = scan_model(path, problems);
  EXPECT_EQ(problems.errors(), 0);
  if (!m.config) return {};
  return structure_properties(*m.config);
}

TEST(PreProperties, ThesisBuildingWithEccentricMassPrintsSixtyCentimetres) {
  // configs/3d-eccentric-v30.yaml: the thesis building with every mass shifted by (0.60, 0.60) m.
  const auto dir = scratch_dir("eccentric");
  const auto r = run_pre((source_dir() / "configs/3d-eccentric-v30.yaml").string() + " -o " +
                         dir.string() + " --no-plan");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The printed table: every storey (and the isolation layer) e_x = e_y = 0.600 m.
  for (const char* storey : {"isolation", "storey 1", "storey 2", "storey 3"}) {
    const auto at = r.output.find(std::string("  ") + storey + " ");
    ASSERT_NE(at, std::string::npos) << storey;
    const std::string line = r.output.substr(at, r.output.find('\n', at) - at);
    EXPECT_NE(line.find("0.600    0.600    0.600    0.600"), std::string::npos) << line;
  }
  std::ifstream in(dir / "properties.json");
  const auto json = nlohmann::json::parse(in);
  for (const auto& s : json["structures"][0]["storeys"]) {
    EXPECT_NEAR(s["eccentricity_m"][0].get<double>(), 0.60, 1e-9) << s["storey"];
    EXPECT_NEAR(s["eccentricity_m"][1].get<double>(), 0.60, 1e-9) << s["storey"];
    EXPECT_NEAR(s["centre_of_stiffness_m"][0].get<double>(), 0.0, 1e-9);
  }
  std::filesystem::remove_all(dir);
}

TEST(PreProperties, StifferColumnsOnOneSideMoveTheCentreOfStiffness) {
  // Four columns at (+-3, +-3) m, 3 m storey: east ones 60 x 60 cm, west ones 40 x 40 cm.
  // By hand: k = 12 E I / h^3 with I = b^4 / 12, so k is proportional to b^4 and
  // x_S = 3 (0.6^4 - 0.4^4) / (0.6^4 + 0.4^4) = 2.0103 m; y_S = 0 by symmetry.
  // Torsion about S: K_theta = sum k_y (x - x_S)^2 + k_x y^2 + sum G J / h.
  const auto dir = scratch_dir("stiff-side");
  const std::string path = write_model(dir, R"(structures:
  - name: a
    isolated: false
    plan: {rectangle: [6 m, 6 m]}
    columns: {E: 30 GPa, nu: 0.2}
    storeys:
      - height: 3 m
        mass: 100 t
        columns:
          - {at: [3 m, -3 m], section: [60 cm, 60 cm]}
          - {at: [3 m, 3 m], section: [60 cm, 60 cm]}
          - {at: [-3 m, 3 m], section: [40 cm, 40 cm]}
          - {at: [-3 m, -3 m], section: [40 cm, 40 cm]}
)");
  const auto p = properties_of(path);
  ASSERT_EQ(p.size(), 1u);
  ASSERT_EQ(p[0].storeys.size(), 1u);
  const StoreyProperties& s = p[0].storeys[0];
  const double e = 30e9, g = e / 2.4, h = 3.0;
  const double k6 = 12 * e * std::pow(0.6, 4) / 12 / (h * h * h);
  const double k4 = 12 * e * std::pow(0.4, 4) / 12 / (h * h * h);
  const double xs = 3 * (k6 - k4) / (k6 + k4);
  EXPECT_NEAR(xs, 2.0103, 1e-4);
  EXPECT_NEAR(s.p_WS.x, xs, 1e-9);
  EXPECT_NEAR(s.p_WS.y, 0.0, 1e-9);
  EXPECT_NEAR(s.k_x, 2 * (k6 + k4), 1e-6 * s.k_x);
  // Saint-Venant J of a square a x a: a^4 (1/3 - 0.21 (1 - 1/12)) (model_input3d.cpp's formula).
  const auto j = [](double a) { return std::pow(a, 4) * (1.0 / 3 - 0.21 * (1 - 1.0 / 12)); };
  const double k_theta = 2 * k6 * std::pow(3 - xs, 2) + 2 * k4 * std::pow(-3 - xs, 2) +
                         2 * (k6 + k4) * 9 + 2 * g * (j(0.6) + j(0.4)) / h;
  EXPECT_NEAR(s.k_theta, k_theta, 1e-9 * k_theta);
  EXPECT_NEAR(s.r_x, std::sqrt(k_theta / s.k_y), 1e-12);
  // Mass at the centroid: e = CM - CS = (-x_S, 0).
  EXPECT_NEAR(s.eccentricity.x, -xs, 1e-9);
  std::filesystem::remove_all(dir);
}

TEST(PreProperties, CentreOfStiffnessOfRotatedColumnsRemovesTheCoupling) {
  // Full coupling with rotated, rectangular columns: about S the translation-rotation terms of
  // the storey stiffness vanish (an independent check of the 2 x 2 solve).
  std::vector<Column3DConfig> cols;
  const Vec2 at[] = {{-4, -2}, {5, -3}, {6, 4}, {-3, 5}};
  for (int i = 0; i < 4; ++i) {
    Column3DConfig c;
    c.position = at[i];
    c.I11 = 0.002 * (i + 1);
    c.I22 = 0.005;
    c.J = 0.003;
    c.E = 30e9;
    c.G = 12e9;
    c.orientation = 0.3 * i;
    cols.push_back(c);
  }
  const Eigen::Matrix3d k = storey_stiffness(cols, 3.2, ColumnCoupling::kFull);
  Vec2 s;
  double k_theta = 0;
  centre_of_stiffness(k, s, k_theta);
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  A(0, 2) = s.y;
  A(1, 2) = -s.x;
  const Eigen::Matrix3d ks = A.transpose() * k * A;
  EXPECT_NEAR(ks(0, 2), 0.0, 1e-9 * k(0, 0));
  EXPECT_NEAR(ks(1, 2), 0.0, 1e-9 * k(0, 0));
  EXPECT_NEAR(ks(2, 2), k_theta, 1e-12 * k_theta);
  // Moving S moves no coupling back: the same columns shifted by (10, -20) give S + (10, -20).
  for (Column3DConfig& c : cols) c.position = c.position + Vec2{10, -20};
  Vec2 s2;
  double k2 = 0;
  centre_of_stiffness(storey_stiffness(cols, 3.2, ColumnCoupling::kFull), s2, k2);
  EXPECT_NEAR(s2.x, s.x + 10, 1e-9);
  EXPECT_NEAR(s2.y, s.y - 20, 1e-9);
  EXPECT_NEAR(k2, k_theta, 1e-9 * k_theta);
}

}  // namespace
}  // namespace isopound::pre::test

namespace isopound::pre::test {
namespace {

TEST(PreGeometry, ClosestPointsOfFacingEdgesAreTheMiddleOfTheirCommonStretch) {
  // a = [-3, 3]^2, b = [3.2, 9.2] x [-2, 4]: facing edges x = 3 and x = 3.2 share y in [-2, 3].
  const std::vector<Vec2> a{{-3, -3}, {3, -3}, {3, 3}, {-3, 3}};
  const std::vector<Vec2> b{{3.2, -2}, {9.2, -2}, {9.2, 4}, {3.2, 4}};
  Vec2 pa, pb;
  closest_points(a, b, pa, pb);
  EXPECT_NEAR(pa.x, 3.0, 1e-12);
  EXPECT_NEAR(pb.x, 3.2, 1e-12);
  EXPECT_NEAR(pa.y, 0.5, 1e-12);
  EXPECT_NEAR(pb.y, 0.5, 1e-12);
  EXPECT_EQ(side_name(pb - pa), "east");
  EXPECT_EQ(side_name(pa - pb), "west");
  EXPECT_EQ(side_name({0.1, -2}), "south");
}

}  // namespace
}  // namespace isopound::pre::test

namespace isopound::pre::test {
namespace {

// configs/3d-mid-storey-isolation.yaml: isolated above storey 1 (4 m podium, slab 1.5 m above
// floor 1). Levels in elevation order; the isolation layer between storeys 1 and 2, its
// stiffness the 16 bearings' K_post = m (2 pi / T_b)^2 with m the 1270 t above them.
TEST(PreProperties, MidStoreyIsolationLevelsAndLayerInPlace) {
  const auto p = properties_of((source_dir() / "configs/3d-mid-storey-isolation.yaml").string());
  ASSERT_EQ(p.size(), 2u);
  const char* levels[] = {"floor 1", "base", "floor 2", "floor 3", "floor 4"};
  const double z[] = {4.0, 5.5, 8.7, 11.9, 15.1};
  ASSERT_EQ(p[0].diaphragms.size(), 5u);
  for (std::size_t l = 0; l < 5; ++l) {
    EXPECT_EQ(p[0].diaphragms[l].level, levels[l]);
    EXPECT_NEAR(p[0].diaphragms[l].elevation, z[l], 1e-12);
  }
  const char* storeys[] = {"storey 1", "isolation", "storey 2", "storey 3", "storey 4"};
  ASSERT_EQ(p[0].storeys.size(), 5u);
  for (std::size_t s = 0; s < 5; ++s) EXPECT_EQ(p[0].storeys[s].label, storeys[s]);
  const double k_b = 1270e3 * std::pow(2.0 * std::acos(-1.0) / 2.0, 2);
  EXPECT_NEAR(p[0].storeys[1].k_x, k_b, 1e-9 * k_b);
  EXPECT_NEAR(p[0].storeys[1].k_y, k_b, 1e-9 * k_b);
}

}  // namespace
}  // namespace isopound::pre::test
