// BearingLink kinematics (d = (u - y theta, v + x theta), torque x F_y - y F_x), its tangent
// T^T (K + c K_v) T against finite differences, planar use; make_bearing_material vs the 2D rules.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "solver/core/constants.h"
#include "solver/elements/bearing_link.h"
#include "solver/materials/linear_biaxial.h"
#include "solver/structures/bearing.h"
#include "solver/structures/isolator.h"

namespace isopound {
namespace {

using Eigen::Vector2d;
using Eigen::VectorXd;

// A 3-DOF diaphragm (u, v, theta) at DOFs 1, 2, 0 (not in order, to catch index mix-ups).
DiaphragmDofs plan_dofs() {
  DiaphragmDofs d;
  d.ux = 1;
  d.uy = 2;
  d.theta = 0;
  return d;
}

TEST(BearingLink, PureRotationDeformsByMinusYThetaXThetaAndGivesTheTorque) {
  const double k = 3e7, x = 4.5, y = -2.0, theta = 1e-3;
  BearingLink link("b", plan_dofs(), Vector2d(x, y), std::make_unique<LinearBiaxialMaterial>(k));
  VectorXd u = VectorXd::Zero(3), v = VectorXd::Zero(3);
  u[0] = theta;
  v[0] = 2 * theta;
  link.set_trial(u, v);
  EXPECT_DOUBLE_EQ(link.law().deformation()[0], -y * theta);
  EXPECT_DOUBLE_EQ(link.law().deformation()[1], x * theta);
  VectorXd f = VectorXd::Zero(3);
  link.add_force(f);
  const Vector2d F = k * Vector2d(-y * theta, x * theta);
  EXPECT_DOUBLE_EQ(f[1], F[0]);
  EXPECT_DOUBLE_EQ(f[2], F[1]);
  EXPECT_NEAR(f[0], x * F[1] - y * F[0], 1e-12 * std::abs(f[0]));
  // A linear spring stores k |d|^2/2 = k (x^2 + y^2) theta^2/2; the power is F . d'.
  EXPECT_NEAR(link.stored_energy(), 0.5 * k * (x * x + y * y) * theta * theta, 1e-9);
  EXPECT_NEAR(link.power(v), F.dot(Vector2d(-y, x) * 2 * theta), 1e-9);
  // Rotational stiffness k (x^2 + y^2) in K(theta, theta).
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
  link.add_tangent(K, 0.0);
  EXPECT_NEAR(K(0, 0), k * (x * x + y * y), 1e-6);
  EXPECT_NEAR(K(0, 1), -y * k, 1e-6);
  EXPECT_NEAR(K(0, 2), x * k, 1e-6);
  EXPECT_TRUE(link.symmetric_tangent());
  ASSERT_EQ(link.output_count(), 9);
  EXPECT_EQ(link.output_name(0), "force");
  EXPECT_EQ(link.output_name(8), "z_y");
  EXPECT_NEAR(link.output(0), F.norm(), 1e-9);
  EXPECT_NEAR(link.output(6), x * theta, 1e-15);
}

// The Newmark tangent dR/du = df/du + (2/h) df/dv against central differences of add_force
// along the Newmark relation v = v0 + (2/h) (u - u0): coupled Bouc-Wen (non-symmetric) and the
// friction pendulum (rate tangent), each after a committed history.
TEST(BearingLink, TangentWithVelocityFactorMatchesFiniteDifferences) {
  const double m = 1.27e6 / 16;
  BearingConfig bw;
  bw.model = BearingConfig::Model::kBoucWenCoupled;
  BearingConfig fp;
  fp.model = BearingConfig::Model::kFrictionPendulum;
  fp.radius = 2.5;
  fp.mu_slow = 0.03;
  fp.mu_fast = 0.09;
  fp.rate_parameter = 25;
  fp.yield_displacement = 5e-4;
  for (const BearingConfig& config : {bw, fp}) {
    BearingLink link("b", plan_dofs(), Vector2d(2.0, 3.0), make_bearing_material(config, m));
    EXPECT_FALSE(link.symmetric_tangent());
    const double c = 2.0 / 0.005;  // 2/h
    VectorXd u0(3), v0(3);
    SCOPED_TRACE(static_cast<int>(config.model));
    u0 << 0.002, 0.03, -0.01;  // theta, u, v
    v0 << 0.001, -0.03, 0.05;  // slow (mu still varies) and not along z
    link.set_trial(u0, v0);
    link.commit();
    VectorXd du(3);
    du << 1e-5, 2e-4, 1e-4;
    const VectorXd u = u0 + du, v = v0 + c * du;
    link.set_trial(u, v);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
    link.add_tangent(K, c);
    Eigen::MatrixXd K_fd(3, 3);
    const double h = 1e-9;
    for (int j = 0; j < 3; ++j) {
      VectorXd e = VectorXd::Unit(3, j) * h;
      VectorXd fp_plus = VectorXd::Zero(3), fp_minus = VectorXd::Zero(3);
      link.set_trial(u + e, v + c * e);
      link.add_force(fp_plus);
      link.set_trial(u - e, v - c * e);
      link.add_force(fp_minus);
      K_fd.col(j) = (fp_plus - fp_minus) / (2 * h);
    }
    // Central differences with h = 1e-9 m: truncation and round-off ~1e-6 of K's largest entry.
    EXPECT_LE((K - K_fd).cwiseAbs().maxCoeff(), 1e-5 * K.cwiseAbs().maxCoeff()) << K << "\n"
                                                                                << K_fd;
    EXPECT_GT(std::abs(K(1, 2) - K(2, 1)), 1e-3 * K.cwiseAbs().maxCoeff());  // really coupled
  }
}

TEST(BearingLink, PlanarUseActsAlongXOnlyWithTheUniaxialOutputNames) {
  DiaphragmDofs dofs;
  dofs.ux = 0;
  BearingConfig fp;
  fp.model = BearingConfig::Model::kFrictionPendulum;
  fp.radius = 2.0;
  fp.mu_slow = fp.mu_fast = 0.05;
  fp.yield_displacement = 5e-4;
  BearingLink link("iso", dofs, Vector2d(1.0, 2.0), make_bearing_material(fp, 1e5));
  EXPECT_TRUE(link.symmetric_tangent());  // a 1x1 block
  ASSERT_EQ(link.output_count(), 3);
  EXPECT_EQ(link.output_name(0), "force");
  EXPECT_EQ(link.output_name(1), "deformation");
  EXPECT_EQ(link.output_name(2), "z");
  VectorXd u(1), v(1);
  u << -0.1;
  v << -0.3;
  link.set_trial(u, v);
  const double W = 1e5 * kGravity;
  EXPECT_NEAR(link.output(0), W * -0.1 / 2.0 - 0.05 * W, 1e-9 * W);
  EXPECT_DOUBLE_EQ(link.output(1), -0.1);
  EXPECT_DOUBLE_EQ(link.output(2), -1.0);
  EXPECT_DOUBLE_EQ(link.law().deformation()[1], 0.0);
}

// make_bearing_material uses the 2D rules (isolator_properties) for the same numbers.
TEST(MakeBearingMaterial, ReproducesIsolatorPropertiesForTheSameNumbers) {
  const double m = 1.27e6 / 16;
  for (const bool yield_force : {false, true}) {
    BearingConfig c;
    c.period = 2.5;
    c.strength_ratio = 0.1;
    c.yield_displacement = 0.015;
    c.strength_is_yield_force = yield_force;
    IsolatorConfig iso;
    iso.period = c.period;
    iso.strength_ratio = c.strength_ratio;
    iso.yield_displacement = c.yield_displacement;
    iso.strength_is_yield_force = yield_force;
    const IsolatorProperties p = isolator_properties(iso, m);
    // By hand: K_post = m (2 pi/T_b)^2, Q = QW m g.
    const double k_post = m * std::pow(2 * std::numbers::pi / 2.5, 2);
    EXPECT_NEAR(p.post_yield_stiffness, k_post, 1e-9 * k_post);
    const double q = 0.1 * m * kGravity;
    EXPECT_NEAR(p.yield_force, yield_force ? q : q + k_post * 0.015, 1e-9 * q);

    const IsolatorProperties pb = bearing_properties(c, m);
    EXPECT_EQ(pb.post_yield_stiffness, p.post_yield_stiffness);
    EXPECT_EQ(pb.yield_force, p.yield_force);
    EXPECT_EQ(pb.elastic_stiffness, p.elastic_stiffness);
    using M = BearingConfig::Model;
    for (const M model : {M::kLinear, M::kBilinear, M::kBoucWenCoupled, M::kBoucWenUncoupled}) {
      c.model = model;
      auto law = make_bearing_material(c, m);
      // Initial stiffness: K_post for the linear law, K_el for the others.
      law->set_trial(Vector2d(1e-9, 0), Vector2d::Zero());
      const double k0 = model == M::kLinear ? p.post_yield_stiffness : p.elastic_stiffness;
      EXPECT_NEAR(law->tangent()(0, 0), k0, 1e-6 * k0);
      EXPECT_NEAR(law->tangent()(1, 1), k0, 1e-6 * k0);
      if (model == M::kLinear) continue;
      // Far beyond yield (40 u_y along y): F = alpha K_el d + (1 - alpha) F_y (z = 1 to 1e-30).
      law->revert();
      for (int k = 1; k <= 400; ++k) {
        law->set_trial(Vector2d(0, 0.1 * k * c.yield_displacement), Vector2d::Zero());
        law->commit();
      }
      const double d = 40 * c.yield_displacement;
      EXPECT_NEAR(law->force()[1], p.alpha * p.elastic_stiffness * d + p.characteristic_strength,
                  1e-9 * p.yield_force);
      EXPECT_NEAR(law->force()[0], 0.0, 1e-9 * p.yield_force);
    }
  }
  BearingConfig bad;
  bad.model = BearingConfig::Model::kBilinear;
  bad.strength_ratio = 1e-4;  // taken as F_y, below K_post u_y: alpha >= 1
  bad.strength_is_yield_force = true;
  EXPECT_THROW(make_bearing_material(bad, m), std::invalid_argument);
  EXPECT_THROW(make_bearing_material(BearingConfig{}, 0.0), std::invalid_argument);
  BearingConfig fp;
  fp.model = BearingConfig::Model::kFrictionPendulum;  // R = 0
  EXPECT_THROW(make_bearing_material(fp, m), std::invalid_argument);
}

}  // namespace
}  // namespace isopound
