// Isolation at any storey, 3D buildings (issue 27 item 2, docs/isolation-level.md, "3D buildings"):
// level 0 is today's model bit for bit; the periods of a building isolated above storey 1 against
// an eigen-solution assembled by hand (a symmetric plan: x, y and torsion uncoupled chains); the
// bearing between two diaphragms (forces equal and opposite, tangent by central differences);
// level matching with a fixed-base neighbour; the energy balance with pounding at the isolated
// slab; bad input.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "solver/core/analysis.h"
#include "solver/core/modes.h"
#include "solver/elements/bearing_link.h"
#include "solver/io/model_input.h"
#include "solver/materials/linear_biaxial.h"
#include "solver/structures/building3d.h"
#include "solver/structures/job.h"
#include "solver/structures/levels3d.h"
#include "solver/structures/pounding3d.h"
#include "test_support.h"

namespace isopound {
namespace {

// The thesis building (3 x 3 bays of 5.5 m, 16 columns 45 x 45 cm, 3.2 m storeys), isolated
// with `extra` keys added to its entry, under a pulse.
std::string thesis_yaml(const std::string& extra, const std::string& bearing =
                                                      "{model: bouc_wen, "
                                                      "Tb: 2.0 s, QW: 5 %, "
                                                      "uy: 1 cm}") {
  return "structures:\n"
         "  - name: building\n"
         "    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}\n"
         "    columns: {section: [45 cm, 45 cm], E: 30 GPa, nu: 0.2}\n"
         "    storeys: {count: 3, height: 3.2 m, mass: 340 t, roof_mass: 250 t}\n"
         "    base: {mass: 340 t}\n"
         "    bearing: " +
         bearing +
         "\n"
         "    damping: {type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4]}\n" +
         extra +
         "ground_motion:\n"
         "  pulse: {amplitude: 1 m/s, period: 1.5 s, t_peak: 1.5 s, duration: 3 s}\n";
}

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "test.yaml", ".");
}

TEST(IsolationLevel3D, LevelZeroIsTodaysModelBitForBit) {
  ModelConfig without = load_text(thesis_yaml(""));
  ModelConfig with = load_text(thesis_yaml("    isolation_level: 0\n"));
  without.output.histories = with.output.histories = false;
  const JobResult a = run_job(without), b = run_job(with);
  ASSERT_EQ(a.model.size(), b.model.size());
  EXPECT_TRUE(a.model.mass == b.model.mass);
  EXPECT_TRUE(a.model.damping == b.model.damping);
  EXPECT_TRUE(a.model.stiffness == b.model.stiffness);
  ASSERT_EQ(a.analysis.displacement.size(), b.analysis.displacement.size());
  for (std::size_t i = 0; i < a.analysis.displacement.size(); ++i) {
    EXPECT_EQ(a.analysis.displacement[i].value, b.analysis.displacement[i].value) << i;
    EXPECT_EQ(a.analysis.displacement[i].time, b.analysis.displacement[i].time) << i;
  }
  EXPECT_EQ(a.analysis.energy.relative_error, b.analysis.energy.relative_error);
  EXPECT_GT(a.analysis.displacement[0].value, 0.05);  // the pulse moves the base slab
  // Level order of k = 0: the base slab first, at the ground.
  const std::vector<Level3D> levels = levels3d(with.structures3d[0]);
  ASSERT_EQ(levels.size(), 4u);
  EXPECT_EQ(levels[0].name, "base");
  EXPECT_EQ(levels[0].elevation, 0.0);
  EXPECT_EQ(a.model.dofs[a.model.structures[0].level_dofs[0]].label, "building/base (x)");
}

// Symmetric square plan, centred masses: x, y and torsion are three uncoupled chains
// ground - k1 - floor 1 - bearings - base - k2 - floor 2 - k3 - floor 3 (the same in y; in
// torsion with the columns' k (x^2 + y^2) + G J / h and the bearings' k_b (x^2 + y^2)).
TEST(IsolationLevel3D, MidStoreyPeriodsEqualAHandAssembledEigenSolution) {
  const ModelConfig c = load_text(thesis_yaml(
      "    isolation_level: 1\n    isolation_height: 1.5 m\n", "{model: linear, Tb: 2.5 s}"));
  const Building3DConfig& b = c.structures3d[0];
  ASSERT_EQ(b.isolation_level, 1);
  const double h = 3.2, T_b = 2.5;
  const std::vector<Column3DConfig>& columns = b.storeys[0].columns;
  const double m[4] = {340e3, 340e3, 340e3, 250e3};  // floor 1, base, floor 2, floor 3
  const double L = 16.5, r2 = L * L / 6.0;           // polar radius of gyration squared
  double k_x = 0.0, k_t = 0.0, r2_columns = 0.0;
  for (const Column3DConfig& col : columns) {
    const double k = 12.0 * col.E * col.I22 / (h * h * h);
    k_x += k;
    k_t +=
        k * (col.position.x * col.position.x + col.position.y * col.position.y) + col.G * col.J / h;
    r2_columns += col.position.x * col.position.x + col.position.y * col.position.y;
  }
  // Bearings under the storey-2 columns, each carrying (base + floors 2, 3) / 16.
  const double carried = m[1] + m[2] + m[3];
  const double w_b = 2.0 * std::numbers::pi / T_b;
  const double k_bx = carried * w_b * w_b;
  const double k_bt = carried / 16.0 * w_b * w_b * r2_columns;
  const auto chain_periods = [&](double k1, double kb, double k_rest, double mass_factor) {
    // Springs: ground-0 (k1), 0-1 (kb), 1-2 (k_rest), 2-3 (k_rest).
    Eigen::Matrix4d K = Eigen::Matrix4d::Zero(), M = Eigen::Matrix4d::Zero();
    const double k[4] = {k1, kb, k_rest, k_rest};
    for (int i = 0; i < 4; ++i) {
      K(i, i) += k[i];
      if (i > 0) {
        K(i - 1, i - 1) += k[i];
        K(i - 1, i) -= k[i];
        K(i, i - 1) -= k[i];
      }
      M(i, i) = m[i] * mass_factor;
    }
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix4d> eig(K, M);
    std::vector<double> T;
    for (int i = 0; i < 4; ++i)
      T.push_back(2.0 * std::numbers::pi / std::sqrt(eig.eigenvalues()[i]));
    return T;
  };
  std::vector<double> expected;
  for (const auto& chain : {chain_periods(k_x, k_bx, k_x, 1.0), chain_periods(k_x, k_bx, k_x, 1.0),
                            chain_periods(k_t, k_bt, k_t, r2)})
    expected.insert(expected.end(), chain.begin(), chain.end());
  std::sort(expected.rbegin(), expected.rend());

  const LinearModel3D lin = linear_model3d(b, false, false);
  const Modes modes = compute_modes(lin.stiffness, lin.mass, lin.influence.col(0));
  ASSERT_EQ(modes.period.size(), 12);
  for (int i = 0; i < 12; ++i)
    EXPECT_NEAR(modes.period[i], expected[static_cast<std::size_t>(i)],
                1e-9 * expected[static_cast<std::size_t>(i)])
        << "mode " << i + 1;
  // The whole model (with its bearing elements' initial tangents): the same first period.
  EXPECT_GT(expected[0], 2.0);  // the isolation mode
  // Level order: floor 1, base, floor 2, floor 3 at 3.2, 4.7, 7.9, 11.1 m.
  const std::vector<Level3D> levels = levels3d(b);
  const char* names[] = {"floor 1", "base", "floor 2", "floor 3"};
  const double z[] = {3.2, 4.7, 7.9, 11.1};
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(levels[static_cast<std::size_t>(l)].name, names[l]);
    EXPECT_NEAR(levels[static_cast<std::size_t>(l)].elevation, z[l], 1e-12);
  }
  const Model model = build_model(c);
  EXPECT_EQ(model.structures[0].base_level, 1);
  EXPECT_EQ(model.dofs[model.structures[0].level_dofs[1]].label, "building/base (x)");
}

// A bearing on a lower diaphragm: deformation relative to it, forces equal and opposite, the
// tangent B^T k B by central differences of the force.
TEST(IsolationLevel3D, BearingBetweenTwoDiaphragms) {
  const double k = 2.0e6;
  BearingLink link("b", DiaphragmDofs{3, 4, 5}, Eigen::Vector2d(2.0, -1.5),
                   std::make_unique<LinearBiaxialMaterial>(k), DiaphragmDofs{0, 1, 2});
  Eigen::VectorXd u(6), v = Eigen::VectorXd::Zero(6);
  u << 0.01, -0.02, 0.003, 0.05, 0.01, -0.002;
  link.set_trial(u, v);
  const Eigen::Vector2d d = link.deformation_of(u);
  // Upper point (2, -1.5) moves (u + 1.5 theta, v + 2 theta), the lower one likewise.
  EXPECT_NEAR(d.x(), (0.05 + 1.5 * -0.002) - (0.01 + 1.5 * 0.003), 1e-15);
  EXPECT_NEAR(d.y(), (0.01 + 2.0 * -0.002) - (-0.02 + 2.0 * 0.003), 1e-15);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6);
  link.add_force(f);
  EXPECT_NEAR((f.head<3>() + f.tail<3>()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(f[3], k * d.x(), 1e-9);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
  link.add_tangent(K, 0.0);
  const double eps = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Eigen::VectorXd up = u, um = u;
    up[j] += eps;
    um[j] -= eps;
    Eigen::VectorXd fp = Eigen::VectorXd::Zero(6), fm = Eigen::VectorXd::Zero(6);
    link.set_trial(up, v);
    link.add_force(fp);
    link.set_trial(um, v);
    link.add_force(fm);
    const Eigen::VectorXd column = (fp - fm) / (2.0 * eps);
    EXPECT_LT((column - K.col(j)).norm(), 1e-6 * K.norm()) << "DOF " << j;
  }
  std::vector<int> dofs;
  link.add_dofs(dofs);
  EXPECT_EQ(dofs.size(), 6u);
}

// A fixed-base neighbour whose storeys (3.2, 1.5, 3.2, 3.2 m) put its floors at the mid-storey
// isolated building's levels (3.2, 4.7, 7.9, 11.1 m): every level pairs with the one at its
// elevation, the isolated slab included.
TEST(IsolationLevel3D, NeighbourLevelsPairByElevation) {
  const std::string neighbour =
      "  - name: neighbour\n"
      "    isolated: false\n"
      "    adjacent: {to: building, side: east, gap: 10 cm}\n"
      "    grid: {bays_x: [5.5 m, 5.5 m, 5.5 m], bays_y: [5.5 m, 5.5 m, 5.5 m]}\n"
      "    plan: {rectangle: [16.85 m, 16.85 m]}\n"
      "    columns: {section: [35 cm, 35 cm], E: 30 GPa, nu: 0.2}\n"
      "    storeys:\n"
      "      - {height: 3.2 m, mass: 200 t}\n"
      "      - {height: 1.5 m, mass: 200 t}\n"
      "      - {height: 3.2 m, mass: 200 t}\n"
      "      - {height: 3.2 m, mass: 200 t}\n"
      "    damping: {type: rayleigh, ratios: [5 %, 5 %], modes: [1, 3]}\n";
  std::string text = thesis_yaml("    isolation_level: 1\n    isolation_height: 1.5 m\n");
  text.insert(text.find("ground_motion:"), neighbour);
  // The slabs reach the outer faces of the edge columns (configs/3d-adjacent-2storey-east.yaml).
  text.insert(text.find("    columns:"), "    plan: {rectangle: [16.95 m, 16.95 m]}\n");
  const ModelConfig c = load_text(text);
  std::vector<std::string> labels;
  for (const ContactPair3D& p : contact_pairs3d(site_bodies(c), c.contact3d))
    labels.push_back(p.label);
  std::sort(labels.begin(), labels.end());
  const std::vector<std::string> expected = {
      "building/base|neighbour/floor 2", "building/floor 1|neighbour/floor 1",
      "building/floor 2|neighbour/floor 3", "building/floor 3|neighbour/floor 4"};
  EXPECT_EQ(labels, expected);
}

// Walls at 8 cm around the isolated slab (floor 1 below it, Bouc-Wen bearings), non-classical
// damping (the substructure's Rayleigh, the superstructure's relative to the slab, the isolation
// dashpot between floor 1 and the slab), a strong pulse at an angle: the slab pounds the walls and
// the energy balance closes to 1e-6. Its error is the trapezoidal integration's of the powers:
// 1.1e-5, 2.6e-6, 4.6e-7, 9.9e-8 at tolerances 1e-6..1e-9 (4 cm walls), hence 1e-8 here.
TEST(IsolationLevel3D, EnergyBalanceWithPoundingAtTheIsolatedSlab) {
  std::string text = thesis_yaml(
      "    isolation_level: 1\n    isolation_height: 1.5 m\n"
      "    walls: {gap: 8 cm}\n");
  text.replace(text.find("{type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4]}"),
               std::string("{type: rayleigh, ratios: [5 %, 2 %], modes: [1, 4]}").size(),
               "{type: non_classical, ratios: [5 %, 2 %], modes: [1, 4], isolation: 5 %}");
  ModelConfig c = load_text(text);
  EXPECT_EQ(c.structures3d[0].damping.type, Damping3DConfig::Type::kNonClassical);
  c.ground_motion.angle = std::numbers::pi / 6;  // 30 degrees: the slab moves in x and y
  c.analysis.tolerance = 1e-8;
  c.output.histories = false;
  const JobResult job = run_job(c);
  int walls = 0;
  double peak_force = 0.0;
  for (std::size_t i = 0; i < job.model.elements.size(); ++i)
    if (job.model.elements[i]->label().find("building/base|wall") == 0) {
      ++walls;
      peak_force = std::max(peak_force, job.analysis.element_outputs[i][0].value);
    }
  EXPECT_EQ(walls, 4);
  EXPECT_GT(peak_force, 0.0);  // the slab pounds the walls
  const EnergyBalance& e = job.analysis.energy;
  EXPECT_LT(e.relative_error, 1e-6) << "max over time " << e.max_relative_error;
  std::printf("energy balance: relative error %.3g (max over time %.3g), wall force %.4g kN\n",
              e.relative_error, e.max_relative_error, peak_force / 1e3);
}

TEST(IsolationLevel3D, BadInputNamesFileLineAndKey) {
  const auto error_of = [](const std::string& text) {
    try {
      load_text(text);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string e = error_of(thesis_yaml("    isolation_level: 3\n    isolation_height: 1 m\n"));
  EXPECT_NE(e.find("test.yaml:"), std::string::npos) << e;
  EXPECT_NE(e.find("isolation_level"), std::string::npos) << e;
  e = error_of(thesis_yaml("    isolation_level: 1\n"));
  EXPECT_NE(e.find("isolation_height"), std::string::npos) << e;
  e = error_of(thesis_yaml("    isolation_height: 1 m\n"));
  EXPECT_NE(e.find("isolation_height: only used with isolation_level > 0"), std::string::npos) << e;
  e = error_of(thesis_yaml("    walls: {gap: 5 cm, level: 4}\n"));
  EXPECT_NE(e.find("walls.level: no level 4"), std::string::npos) << e;
}

// Issue 37: the shipped 3D mid-storey config analysed its record and then crashed (SIGSEGV)
// writing summary.json: the 2D ground-shear entry read storey shears a 3D building does not
// have. It ends with exit 0 and a summary that names its isolation level and height.
TEST(IsolationLevel3D, ShippedConfigWritesItsSummary) {
  ISOPOUND_REQUIRE_RECORDS();
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("isopound-mid3d-" + std::to_string(::getpid()));
  const test::CommandResult r = test::run_isopound(
      "run " + (test::source_dir() / "configs" / "3d-mid-storey-isolation.yaml").string() +
      " --until 0.2 -q -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& b = j.at("buildings_3d").at(0);
  EXPECT_EQ(b.at("isolation_level").get<int>(), 1);
  EXPECT_DOUBLE_EQ(b.at("isolation_height_m").get<double>(), 1.5);
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace isopound
