// Bearings under a rigid diaphragm (u, v, theta) in a time-history analysis: four bearings of a
// doubly symmetric slab excited along x reproduce the 2D isolator; an eccentric layout twists
// and closes its energy balance (BearingLink power and stored energy in coupled motion).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "solver/core/analysis.h"
#include "solver/elements/bearing_link.h"
#include "solver/elements/uniaxial_link.h"
#include "solver/excitation/ground_motion.h"
#include "solver/structures/bearing.h"
#include "solver/structures/isolator.h"

namespace isopound {
namespace {

constexpr double kSlabMass = 1.27e6;          // kg, the whole thesis building as one slab
constexpr double kPolarMoment = 1.27e6 * 25;  // kg m^2 (radius of gyration 5 m)

Model slab_2d(const IsolatorConfig& iso) {
  Model m;
  m.grow(1);
  m.dofs.push_back({"slab/u", 0, 0});
  m.mass(0, 0) = kSlabMass;
  m.influence[0] = 1.0;
  m.elements.push_back(
      std::make_unique<UniaxialLink>("iso", kGround, 0, make_isolator_material(iso, kSlabMass)));
  return m;
}

// DOFs (u, v, theta); bearings at the given plan positions, each carrying m / count.
Model slab_3d(const BearingConfig& bearing, const std::vector<Eigen::Vector2d>& positions) {
  Model m;
  m.grow(3);
  m.dofs = {{"slab/u", 0, 0}, {"slab/v", 0, 0}, {"slab/theta", 0, 0}};
  m.mass(0, 0) = m.mass(1, 1) = kSlabMass;
  m.mass(2, 2) = kPolarMoment;
  m.influence[0] = 1.0;
  DiaphragmDofs dofs;
  dofs.ux = 0;
  dofs.uy = 1;
  dofs.theta = 2;
  const double share = kSlabMass / static_cast<double>(positions.size());
  for (const Eigen::Vector2d& p : positions)
    m.elements.push_back(
        std::make_unique<BearingLink>("bearing", dofs, p, make_bearing_material(bearing, share)));
  return m;
}

double column_max_abs(const History& h, int col) {
  double peak = 0.0;
  for (std::size_t r = 0; r < h.rows(); ++r)
    peak = std::max(peak, std::abs(h.values[r * h.columns.size() + col]));
  return peak;
}

// K_post, Q and F_y are proportional to the carried mass, so four bearings of m/4 are the 2D
// isolator of m: with theta = v = 0 exactly (the forces are equal and the torque sums cancel
// exactly), every step is the 2D step. u agrees to round-off (measured 9e-15 of its peak;
// 1e-9 asserted).
TEST(BearingDiaphragm, DoublySymmetricSlabExcitedAlongXIsThe2DIsolator) {
  const GroundMotion pulse = make_pulse(PulseParameters{});
  const std::vector<Eigen::Vector2d> corners = {{4, 3}, {-4, 3}, {-4, -3}, {4, -3}};
  struct Case {
    IsolatorConfig::Model iso;
    BearingConfig::Model bearing;
  };
  for (const Case c :
       {Case{IsolatorConfig::Model::kBoucWen, BearingConfig::Model::kBoucWenCoupled},
        Case{IsolatorConfig::Model::kBilinear, BearingConfig::Model::kBilinear},
        Case{IsolatorConfig::Model::kBoucWen, BearingConfig::Model::kBoucWenUncoupled}}) {
    IsolatorConfig iso;
    iso.model = c.iso;
    BearingConfig bearing = bearing_config(iso);
    bearing.model = c.bearing;
    Model planar = slab_2d(iso);
    Model plan = slab_3d(bearing, corners);
    RunOptions options;
    options.output.interval = 0.0;
    const AnalysisResult r2 = run_analysis(planar, pulse, options);
    const AnalysisResult r3 = run_analysis(plan, pulse, options);
    ASSERT_EQ(r2.history.rows(), r3.history.rows());
    const std::size_t w2 = r2.history.columns.size(), w3 = r3.history.columns.size();
    const double peak = r2.displacement[0].value;
    EXPECT_GT(peak, 0.1);  // well into the nonlinear range (u_y = 1 cm)
    double worst = 0.0;
    for (std::size_t row = 0; row < r2.history.rows(); ++row)
      worst = std::max(worst, std::abs(r3.history.values[row * w3 + 2] -
                                       r2.history.values[row * w2 + 2]));  // "slab/u u [m]"
    EXPECT_LE(worst, 1e-9 * peak) << static_cast<int>(c.bearing);
    EXPECT_EQ(column_max_abs(r3.history, 3), 0.0);  // v
    EXPECT_EQ(column_max_abs(r3.history, 4), 0.0);  // theta
    EXPECT_EQ(r2.stats.steps, r3.stats.steps);
  }
}

// Bearings placed off-centre (centre of stiffness at (0.2, 2.8) m, the centre of mass at 0): an
// x excitation twists the slab and moves it in y through the coupling, and the energy balance
// of the model (element work from BearingLink::power, recoverable energy from the laws)
// closes to 1e-4 of the input at a fixed step of 1 ms (measured 3e-10 to 2e-6). Every law,
// including the non-symmetric coupled Bouc-Wen and friction pendulum (with this branch's
// symmetric factorisation of K_hat their Newton iteration is a quasi-Newton one, and still
// converges; the LU of issue 10's stepper makes it exact).
TEST(BearingDiaphragm, EccentricLayoutTwistsAndClosesTheEnergyBalance) {
  const GroundMotion pulse = make_pulse(PulseParameters{});
  const std::vector<Eigen::Vector2d> layout = {{5, 6}, {-4, 6}, {-4, -2}, {4, -2}, {0, 6}};
  using M = BearingConfig::Model;
  for (const M model :
       {M::kBilinear, M::kBoucWenUncoupled, M::kLinear, M::kBoucWenCoupled, M::kFrictionPendulum}) {
    SCOPED_TRACE(static_cast<int>(model));
    BearingConfig bearing;
    bearing.model = model;
    if (model == M::kFrictionPendulum) {
      bearing.radius = 2.2;
      bearing.mu_slow = 0.04;
      bearing.mu_fast = 0.10;
      bearing.rate_parameter = 30;
      bearing.yield_displacement = 5e-4;
    }
    Model plan = slab_3d(bearing, layout);
    RunOptions options;
    options.analysis.stepping = AnalysisConfig::Stepping::kFixed;
    options.analysis.dt = 1e-3;
    options.output.histories = false;
    const AnalysisResult r = run_analysis(plan, pulse, options);
    // Twist (5 m from the centre) and y motion are a sizeable fraction of the x motion.
    EXPECT_GT(r.displacement[2].value * 5.0, 0.05 * r.displacement[0].value) << "no torsion";
    EXPECT_GT(r.displacement[1].value, 1e-3 * r.displacement[0].value) << "no y coupling";
    EXPECT_LT(r.energy.relative_error, 1e-4);
    if (model != M::kLinear) {
      EXPECT_GT(r.energy.hysteretic, 0.0);
    }
  }
}

}  // namespace
}  // namespace isopound
