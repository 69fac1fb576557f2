// Yielding 3D columns (issue 23): the column element's kinematics, its circular interaction
// along a diagonal (analytic), its consistent tangent (central differences), the elastic limit
// of a whole 3D model, the reduction to a 2D shear building with summed bilinear storeys, the
// energy balance with yielding columns, walls and friction, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/core/analysis.h"
#include "solver/core/modes.h"
#include "solver/elements/column_link.h"
#include "solver/elements/uniaxial_link.h"
#include "solver/io/model_input.h"
#include "solver/materials/bilinear.h"
#include "solver/materials/bilinear_biaxial.h"
#include "solver/materials/bouc_wen_coupled.h"
#include "solver/structures/building3d.h"
#include "solver/structures/column_element.h"
#include "solver/structures/job.h"
#include "test_support.h"

namespace isopound {
namespace {

ModelConfig thesis_config(const char* file = "3d-thesis-building.yaml") {
  return load_model_file((test::source_dir() / "configs" / file).string());
}

// A column at plan point p between a diaphragm (DOFs 0, 1, 2) and the ground.
struct SingleColumn {
  Eigen::Vector2d p{2.0, -1.0};
  double orientation = std::numbers::pi / 6;  // 30 degrees
  Eigen::Vector2d d_y{0.016, 0.016}, V_y{2.0e6, 2.0e6};
  double alpha = 0.05;

  ColumnLink make(bool bouc_wen) const {
    ColumnLinkGeometry g{p, orientation, d_y, V_y};
    std::unique_ptr<BiaxialMaterial> law;
    if (bouc_wen) {
      BoucWenParameters bw;
      bw.elastic_stiffness = bw.yield_force = bw.yield_displacement = 1.0;
      bw.alpha = alpha;
      law = std::make_unique<CoupledBoucWenMaterial>(bw);
    } else {
      law = std::make_unique<BilinearBiaxialMaterial>(1.0, alpha, 1.0);
    }
    return ColumnLink("c", DiaphragmDofs{0, 1, 2}, DiaphragmDofs{}, g, std::move(law), alpha);
  }
  // Diaphragm DOFs that move the column's point by d_W with a rotation theta.
  Eigen::VectorXd dofs_for(const Eigen::Vector2d& d_W, double theta) const {
    Eigen::VectorXd u(3);
    u << d_W.x() + p.y() * theta, d_W.y() - p.x() * theta, theta;
    return u;
  }
  Eigen::Vector2d axis(int i) const {
    const double a = orientation + (i == 0 ? 0.0 : std::numbers::pi / 2);
    return {std::cos(a), std::sin(a)};
  }
};

// Radial loading along the diagonal of the section axes: elastic up to the circle |d| = d_y
// (shear |V| = V_y, not the square's sqrt(2) V_y), then V = V_y + alpha k (|d| - d_y) along
// the same direction; the generalised force is T^T V.
TEST(ColumnYield3D, DiagonalLoadYieldsAtTheCircle) {
  const SingleColumn s;
  ColumnLink column = s.make(false);
  const Eigen::Vector2d e = (s.axis(0) + s.axis(1)).normalized();
  const double k = s.V_y[0] / s.d_y[0];
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(3);
  for (int step = 1; step <= 40; ++step) {
    const double r = 0.001 * step;  // |d| up to 0.04 m = 2.5 d_y
    column.set_trial(s.dofs_for(r * e, 1e-3 * step), v);
    column.commit();
    const double expected = r <= s.d_y[0] ? k * r : s.V_y[0] + s.alpha * k * (r - s.d_y[0]);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(3);
    column.add_force(f);
    const Eigen::Vector2d V = column.shear_W();
    EXPECT_NEAR(V.norm(), expected, 1e-9 * expected) << r;
    EXPECT_NEAR(V.normalized().dot(e), 1.0, 1e-12) << r;
    EXPECT_NEAR(f[0], V.x(), 1e-9 * expected);
    EXPECT_NEAR(f[1], V.y(), 1e-9 * expected);
    EXPECT_NEAR(f[2], s.p.x() * V.y() - s.p.y() * V.x(), 1e-9 * expected * s.p.norm());
    double out[11];
    column.outputs(out);
    EXPECT_NEAR(out[1], r, 1e-12);                                  // drift
    EXPECT_NEAR(out[2], r / (std::sqrt(2.0) * s.d_y[0]), 1e-9);     // ductility: per axis
    EXPECT_EQ(out[9], r / std::sqrt(2.0) >= s.d_y[0] ? 1.0 : 0.0);  // yielded, per axis
  }
}

// The coupled Bouc-Wen column on a radial diagonal path saturates on the same circle:
// |V - alpha k d| -> (1 - alpha) V_y (|z| -> (A / (beta + gamma))^(1/n) = 1).
TEST(ColumnYield3D, BoucWenDiagonalSaturatesOnTheCircle) {
  const SingleColumn s;
  ColumnLink column = s.make(true);
  const Eigen::Vector2d e = (s.axis(0) - s.axis(1)).normalized();
  const double k = s.V_y[0] / s.d_y[0];
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(3);
  for (int step = 1; step <= 200; ++step) {
    column.set_trial(s.dofs_for(0.001 * step * e, 0.0), v);
    column.commit();
  }
  const Eigen::Vector2d hysteretic = column.shear_W() - s.alpha * k * 0.2 * e;
  EXPECT_NEAR(hysteretic.norm(), (1.0 - s.alpha) * s.V_y[0], 1e-6 * s.V_y[0]);
}

// The consistent tangent against central differences of the force, on an anisotropic column
// (different yield drift and shear per axis) that has yielded.
TEST(ColumnYield3D, TangentMatchesCentralDifferences) {
  for (const bool bouc_wen : {false, true}) {
    SingleColumn s;
    s.d_y = {0.016, 0.009};
    s.V_y = {2.0e6, 3.0e6};
    ColumnLink column = s.make(bouc_wen);
    const Eigen::VectorXd v = Eigen::VectorXd::Zero(3);
    column.set_trial(s.dofs_for({0.02, 0.011}, 2e-3), v);
    column.commit();
    const Eigen::VectorXd u = s.dofs_for({0.025, 0.013}, 2.5e-3);
    column.set_trial(u, v);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
    column.add_tangent(K, 0.0);
    for (int j = 0; j < 3; ++j) {
      const double h = j == 2 ? 1e-9 : 1e-8;
      Eigen::VectorXd up = u, um = u, fp = Eigen::VectorXd::Zero(3), fm = fp;
      up[j] += h;
      um[j] -= h;
      column.set_trial(up, v);
      column.add_force(fp);
      column.set_trial(um, v);
      column.add_force(fm);
      const Eigen::VectorXd fd = (fp - fm) / (2 * h);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(K(i, j), fd[i], 1e-5 * K.cwiseAbs().maxCoeff())
            << (bouc_wen ? "Bouc-Wen " : "bilinear ") << i << "," << j;
    }
    // The stiffness product is the same tangent.
    column.set_trial(u, v);
    const Eigen::VectorXd x = Eigen::Vector3d(0.3, -0.2, 0.01);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3);
    column.add_stiffness_product(x, y);
    Eigen::MatrixXd K2 = Eigen::MatrixXd::Zero(3, 3);
    column.add_tangent(K2, 0.0);
    EXPECT_LT((y - K2 * x).norm(), 1e-9 * (K2 * x).norm());
  }
}

// Every column of `b` with the given law.
void set_hysteresis(Building3DConfig& b, const ColumnHysteresisConfig& h) {
  for (Storey3DConfig& s : b.storeys)
    for (Column3DConfig& c : s.columns) c.hysteresis = h;
}

ColumnHysteresisConfig bilinear(double yield_drift_ratio, double alpha) {
  ColumnHysteresisConfig h;
  h.law.model = HysteresisModel::kBilinear;
  h.yield_drift_ratio = yield_drift_ratio;
  h.post_yield_ratio = alpha;
  return h;
}

void expect_relative(const std::vector<Peak>& a, const std::vector<Peak>& b, double tol,
                     const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 0.0;
  for (const Peak& p : b) scale = std::max(scale, p.value);
  // Plus round-off of the family: the doubly symmetric building's rotations are exactly 0, and
  // both models give noise of ~1e-16 (elastic) and ~1e-13 (columns as elements) of the scale.
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a[i].value, b[i].value, tol * b[i].value + 1e-12 * scale) << what << " " << i;
}

// The thesis building (isolated, coupled Bouc-Wen bearings) with bilinear columns whose yield
// drift is 100 m: every peak is the elastic model's to 1e-9 relative (default adaptive steps).
TEST(ColumnYield3D, ElasticLimitEqualsTheElasticModel) {
  ModelConfig c = thesis_config();
  c.ground_motion = GroundMotionConfig{};  // the built-in pulse pair
  c.ground_motion.angle = 0.4;
  c.output.histories = false;
  const JobResult elastic = run_job(c);
  set_hysteresis(c.structures3d[0], bilinear(100.0 / 3.2, 0.05));
  const JobResult limit = run_job(c);
  ASSERT_EQ(limit.model.elements.size(), elastic.model.elements.size() + 48);
  expect_relative(limit.analysis.displacement, elastic.analysis.displacement, 1e-9, "u");
  expect_relative(limit.analysis.velocity, elastic.analysis.velocity, 1e-9, "v");
  expect_relative(limit.analysis.absolute_acceleration, elastic.analysis.absolute_acceleration,
                  1e-9, "a");
  // The same probes, then the storey shears (recorded with yielding columns).
  ASSERT_EQ(limit.analysis.probes.size(), elastic.analysis.probes.size() + 3);
  for (std::size_t p = 0; p < elastic.analysis.probes.size(); ++p)
    EXPECT_NEAR(limit.analysis.probes[p].resultant.value,
                elastic.analysis.probes[p].resultant.value,
                1e-9 * elastic.analysis.probes[p].resultant.value)
        << p;
  for (std::size_t e = 0; e < elastic.model.elements.size(); ++e)  // the bearings
    expect_relative(limit.analysis.element_outputs[e], elastic.analysis.element_outputs[e], 1e-9,
                    "bearing");
}

// A doubly symmetric fixed-base building whose 48 columns yield (bilinear), under a pulse along x
// only, against a 2D shear building assembled here from UniaxialLink + BilinearMaterial with the
// summed storey law (16 columns: 16 k, the same yield drift, so 16 V_y, the same alpha), the same
// masses and the x-block of the 3D model's damping: same fixed steps, peaks to 1e-6.
TEST(ColumnYield3D, ReducesToThe2DShearBuildingWithSummedBilinearStoreys) {
  ModelConfig c = thesis_config();
  Building3DConfig& b = c.structures3d[0];
  b.isolated = false;
  const double ratio = 0.005, alpha = 0.05;
  set_hysteresis(b, bilinear(ratio, alpha));
  c.output.histories = false;
  PulseParameters pulse;  // near the fixed-base period 0.31 s: the storeys yield
  pulse.amplitude = 0.6;  // m/s
  pulse.period = 0.4;     // s
  pulse.t_peak = 1.0;
  pulse.duration = 6.0;
  const GroundMotion motion = make_pulse(pulse);
  RunOptions o;
  o.analysis.stepping = AnalysisConfig::Stepping::kFixed;
  o.analysis.dt = 1e-3;
  o.output.histories = false;
  Model model3 = build_model(c);
  ASSERT_EQ(model3.size(), 9);
  const AnalysisResult r3 = run_analysis(model3, motion, o);

  const double h = 3.2, E = 30e9, I = std::pow(0.45, 4) / 12.0;
  const double k_column = 12.0 * E * I / (h * h * h);
  Model model2;
  model2.grow(3);
  for (int l = 0; l < 3; ++l) {
    model2.dofs.push_back({"floor " + std::to_string(l + 1), 0, l, DofKind::kTranslationX, 1.0});
    model2.influence[l] = 1.0;
    for (int m = 0; m < 3; ++m) {
      model2.mass(l, m) = model3.mass(3 * l, 3 * m);
      model2.damping(l, m) = model3.damping(3 * l, 3 * m);
    }
    model2.elements.push_back(std::make_unique<UniaxialLink>(
        "storey " + std::to_string(l + 1), l - 1, l,
        std::make_unique<BilinearMaterial>(16.0 * k_column, alpha, 16.0 * k_column * ratio * h)));
  }
  StructureInfo info;
  info.name = "stick";
  info.level_dofs = {0, 1, 2};
  model2.structures.push_back(info);
  EXPECT_DOUBLE_EQ(model2.mass(0, 0), 340e3);
  const AnalysisResult r2 = run_analysis(model2, motion, o);
  double yielded = 0.0;
  for (int l = 0; l < 3; ++l) {
    for (auto [p3, p2] :
         {std::pair{&r3.displacement, &r2.displacement}, std::pair{&r3.velocity, &r2.velocity},
          std::pair{&r3.absolute_acceleration, &r2.absolute_acceleration}}) {
      EXPECT_NEAR((*p3)[3 * l].value, (*p2)[l].value, 1e-6 * (*p2)[l].value) << l;
      EXPECT_LE((*p3)[3 * l + 1].value, 1e-10) << "y response, level " << l;
      EXPECT_LE((*p3)[3 * l + 2].value, 1e-10) << "rotation, level " << l;
    }
    yielded = std::max(yielded, r2.element_outputs[l][1].value / (ratio * h));
  }
  EXPECT_GT(yielded, 2.0);  // the comparison is inelastic: storey ductility > 2
  EXPECT_NEAR(r3.energy.hysteretic, r2.energy.hysteretic, 1e-6 * r2.energy.hysteretic);
  EXPECT_LT(r3.energy.relative_error, 1e-6);
}

// Isolated on friction pendulum bearings, moat walls at 5 cm, yielding Bouc-Wen columns, a strong
// pulse pair at an angle: the columns yield, the slab pounds the walls, and the energy balance
// closes to 1e-6.
TEST(ColumnYield3D, EnergyBalanceWithYieldingColumnsWallsAndFriction) {
  ModelConfig c = thesis_config();
  Building3DConfig& b = c.structures3d[0];
  ColumnHysteresisConfig h = bilinear(0.002, 0.05);
  h.law.model = HysteresisModel::kBoucWen;
  set_hysteresis(b, h);
  b.bearing.model = BearingConfig::Model::kFrictionPendulum;
  b.bearing.radius = 2.0;
  b.bearing.mu_slow = b.bearing.mu_fast = 0.05;
  b.walls.present = {true, true, true, true};
  b.walls.gap = {0.05, 0.05, 0.05, 0.05};
  c.ground_motion = GroundMotionConfig{};
  c.ground_motion.angle = 0.5;
  c.ground_motion.pulse.duration = 8.0;  // s: the pulse (2-6 s) and 2 s after it
  // The balance's error is that of the trapezoidal integration of the powers over the steps
  // (bench/RESULTS.md: about the tolerance with pounding): 1e-7 for < 1e-6.
  c.analysis.tolerance = 1e-7;
  c.output.histories = false;
  const JobResult job = run_job(c);
  const EnergyBalance& e = job.analysis.energy;
  double ductility = 0.0;
  int contacts = 0;
  for (std::size_t i = 0; i < job.model.elements.size(); ++i) {
    const Element& el = *job.model.elements[i];
    if (el.label().find("/column ") != std::string::npos)
      ductility = std::max(ductility, job.analysis.element_outputs[i][2].value);
    if (el.label().find("wall") != std::string::npos) ++contacts;
  }
  EXPECT_GT(ductility, 1.0);  // the columns yield
  EXPECT_GT(contacts, 0);
  EXPECT_GT(e.hysteretic, 0.0);
  EXPECT_LT(e.relative_error, 1e-6) << "max over time " << e.max_relative_error;
}

// P-Delta: the model's stiffness with p_delta minus without is the geometric stiffness of each
// storey, -(g / h) times the masses above: in x and y -P/h, in torsion -(P/h) (I_p / m) with I_p
// the polar moment about the plan origin (a centred 16.5 m square floor: m (a^2 + b^2) / 12;
// eccentric by e: + m |e|^2, and x-theta, y-theta terms m e), placed between the two levels.
// Then a one-storey building's translational frequency is sqrt((k - P/h) / m) exactly.
TEST(ColumnYield3D, PDeltaGeometricStiffness) {
  ModelConfig c = thesis_config();
  Building3DConfig& b = c.structures3d[0];
  b.isolated = false;
  b.storeys.resize(2);
  b.storeys[1].floor.eccentricity = {0.5, -0.3};
  b.damping.type = Damping3DConfig::Type::kNone;
  b.polar_moment_rule = EccentricPolarMoment::kThesis;
  const Model without = build_model(c);
  b.p_delta = true;
  const Model with = build_model(c);
  const Eigen::MatrixXd kg = with.stiffness - without.stiffness;
  const double h = 3.2, m1 = 340e3, m2 = 340e3, L = 16.5, g = 9.81;
  const Eigen::Vector2d e(0.5, -0.3);
  // The masses about the plan origin: floor 1 centred, floor 2 eccentric.
  Eigen::Matrix3d M1 = Eigen::Matrix3d::Zero(), M2 = Eigen::Matrix3d::Zero();
  M1.diagonal() << m1, m1, m1 * L * L / 6.0;
  M2.diagonal() << m2, m2, m2 * L * L / 6.0 + 2.0 * m2 * e.squaredNorm();  // thesis rule
  M2(0, 2) = M2(2, 0) = -m2 * e.y();
  M2(1, 2) = M2(2, 1) = m2 * e.x();
  const Eigen::Matrix3d k1 = -(g / h) * (M1 + M2), k2 = -(g / h) * M2;
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 6);
  expected.topLeftCorner<3, 3>() = k1 + k2;
  expected.bottomRightCorner<3, 3>() = k2;
  expected.topRightCorner<3, 3>() = -k2;
  expected.bottomLeftCorner<3, 3>() = -k2;
  EXPECT_LT((kg - expected).norm(), 1e-9 * expected.norm()) << kg << "\n\n" << expected;
  EXPECT_DOUBLE_EQ(kg(0, 0), -g * (m1 + 2 * m2) / h);  // -P1/h - P2/h at the lower level

  // One storey: omega^2 = (k - P/h) / m in x.
  b.storeys.resize(1);
  b.storeys[0].floor.eccentricity = {0.0, 0.0};
  const Model one = build_model(c);
  const double k = one.stiffness(0, 0) + g * m1 / h;  // the columns' 16 x 12 E I / h^3
  const double I = std::pow(0.45, 4) / 12.0;
  EXPECT_NEAR(k, 16.0 * 12.0 * 30e9 * I / (h * h * h), 1e-9 * k);
  const Modes modes = compute_modes(one.stiffness, one.mass, one.influence);
  EXPECT_NEAR(modes.omega[0], std::sqrt((k - g * m1 / h) / m1), 1e-9 * modes.omega[0]);
}

ModelConfig load_text(const std::string& text) {
  return load_model(YAML::Load(text), "inline.yaml", "/models");
}

TEST(ColumnYield3D, InputReadsTheLawsAndRefusesBadOnes) {
  const std::string head = R"(structures:
  - name: b
    grid: {bays_x: [5.5 m], bays_y: [5.5 m]}
    columns: {section: [45 cm, 30 cm], E: 30 GPa, nu: 0.2,
              hysteresis: {model: bilinear, yield_drift_ratio: 0.5 %, post_yield_ratio: 5 %}}
    isolated: false
    storeys:
      - {height: 3 m, mass: 100 t}
      - height: 3 m
        mass: 100 t
        hysteresis: {model: bouc_wen, yield_moment: 300 kN m, post_yield_ratio: 2 %, n: 3}
      - height: 3 m
        mass: 100 t
        columns: [{at: [-2.75 m, -2.75 m], hysteresis: {model: elastic}},
                  {at: [2.75 m, 2.75 m], hysteresis: {model: bilinear, yield_drift_ratio: 1 %, post_yield_ratio: 0}}]
)";
  const ModelConfig c = load_text(head);
  const Building3DConfig& b = c.structures3d[0];
  using M = HysteresisModel;
  EXPECT_EQ(b.storeys[0].columns[0].hysteresis.law.model, M::kBilinear);
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].hysteresis.yield_drift_ratio, 0.005);
  EXPECT_DOUBLE_EQ(b.storeys[0].columns[0].hysteresis.post_yield_ratio, 0.05);
  EXPECT_EQ(b.storeys[1].columns[3].hysteresis.law.model, M::kBoucWen);
  EXPECT_DOUBLE_EQ(b.storeys[1].columns[3].hysteresis.yield_moment, 300e3);
  EXPECT_DOUBLE_EQ(b.storeys[1].columns[3].hysteresis.law.bouc_wen.n, 3.0);
  EXPECT_EQ(b.storeys[2].columns[0].hysteresis.law.model, M::kElastic);
  EXPECT_DOUBLE_EQ(b.storeys[2].columns[1].hysteresis.yield_drift_ratio, 0.01);
  // Yield per axis (section 45 x 30 cm): the drift ratio gives one d_y, V_y = k_i d_y; the
  // moment one V_y = 2 M_y / h, d_y,i = V_y / k_i.
  const Column3DConfig& c0 = b.storeys[0].columns[0];
  const ColumnYield y0 = column_yield(c0, 3.0);
  const double k1 = 12.0 * 30e9 * (0.30 * std::pow(0.45, 3) / 12.0) / 27.0;
  EXPECT_DOUBLE_EQ(y0.drift[0], 0.015);
  EXPECT_NEAR(y0.shear[0], k1 * 0.015, 1e-9 * k1);
  const ColumnYield y1 = column_yield(b.storeys[1].columns[0], 3.0);
  EXPECT_DOUBLE_EQ(y1.shear[0], 2.0 * 300e3 / 3.0);
  EXPECT_DOUBLE_EQ(y1.shear[1], 2.0 * 300e3 / 3.0);
  EXPECT_NEAR(y1.drift[0], 2e5 / k1, 1e-12);
  // A model with them builds: 4 + 4 + 1 column elements.
  Model m = build_model(c);
  EXPECT_EQ(m.elements.size(), 9u);

  const auto with = [&](const std::string& from, const std::string& to) {
    std::string s = head;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  struct Bad {
    std::string text;
    int line;
    std::string key;
    std::string what;
  };
  const std::string law =
      "hysteresis: {model: bilinear, yield_drift_ratio: 0.5 %, post_yield_ratio: 5 %}";
  const Bad cases[] = {
      {with("yield_drift_ratio: 0.5 %", "yield_drift_ratio: 0"), 5,
       "structures[0].columns.hysteresis.yield_drift_ratio", ""},
      {with("yield_drift_ratio: 0.5 %", "yield_drift_ratio: -1 %"), 5,
       "structures[0].columns.hysteresis.yield_drift_ratio", ""},
      {with("post_yield_ratio: 5 %}}", "post_yield_ratio: 1}}"), 5,
       "structures[0].columns.hysteresis.post_yield_ratio", "[0, 1)"},
      {with("post_yield_ratio: 5 %}}", "post_yield_ratio: -5 %}}"), 5,
       "structures[0].columns.hysteresis.post_yield_ratio", ""},
      {with("post_yield_ratio: 5 %}}", "post_yield_ratio: 5 %, n: 2}}"), 5,
       "structures[0].columns.hysteresis.n", "is not used with model: bilinear"},
      {with("post_yield_ratio: 2 %, n: 3}", "post_yield_ratio: 2 %, n: 3, yield_drift_ratio: 1 %}"),
       11, "structures[0].storeys[1].hysteresis.yield_moment", "not both"},
      {with("{model: elastic}", "{model: elastic, post_yield_ratio: 0}"), 14,
       "structures[0].storeys[2].columns[0].hysteresis.post_yield_ratio",
       "is not used with model: elastic"},
      {with("yield_drift_ratio: 1 %, post_yield_ratio: 0", "post_yield_ratio: 0"), 15,
       "structures[0].storeys[2].columns[1].hysteresis.yield_drift_ratio", "yield_moment"},
      {with(law, "hysteresis: {model: plastic}"), 5, "structures[0].columns.hysteresis.model",
       "bilinear"},
  };
  for (const Bad& bad : cases) {
    try {
      load_text(bad.text);
      ADD_FAILURE() << "no error for:\n" << bad.text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), bad.line) << e.what();
      EXPECT_EQ(e.key(), bad.key) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.what), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace isopound
