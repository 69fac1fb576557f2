// Biaxial bearing laws: the coupled Bouc-Wen against the uniaxial one on uniaxial orbits,
// circular orbits (|z| <= 1, force on the circle), the uncoupled square corner, tangents vs FD.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "solver/materials/biaxial_uncoupled.h"
#include "solver/materials/bilinear.h"
#include "solver/materials/bilinear_biaxial.h"
#include "solver/materials/bouc_wen.h"
#include "solver/materials/bouc_wen_coupled.h"
#include "solver/materials/friction_pendulum.h"
#include "solver/materials/linear_biaxial.h"

namespace isopound {
namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

// One bearing of the thesis building (1.27e6 kg over 16 bearings, T_b 2 s, Q/W 5 %, u_y 1 cm):
// K_post = m (2 pi/2)^2, F_y = Q + K_post u_y.
BoucWenParameters thesis_bearing(double n = 2.0, double beta = 0.5, double gamma = 0.5) {
  const double m = 1.27e6 / 16;
  const double k_post = m * kPi * kPi;
  BoucWenParameters p;
  p.yield_displacement = 0.01;
  p.yield_force = 0.05 * m * 9.81 + k_post * 0.01;
  p.elastic_stiffness = p.yield_force / 0.01;
  p.alpha = k_post / p.elastic_stiffness;
  p.n = n;
  p.beta = beta;
  p.gamma = gamma;
  p.A = beta + gamma;
  return p;
}

// An irregular deformation history along a line: steps of very different sizes (a fraction of
// a sub-increment up to several u_y), reversals, and several trial states per step as Newton
// would set them, each followed by commit.
struct Trial {
  double d;
  bool commit;
};
std::vector<Trial> irregular_history(double u_y, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Trial> h;
  double d = 0.0;
  for (int k = 0; k < 600; ++k) {
    const double t = 0.05 * k;
    const double target = u_y * (8.0 * std::sin(0.7 * t) + 3.0 * std::sin(2.3 * t + 1.0));
    const double scale = std::pow(10.0, -3.0 + 3.5 * unit(rng));  // 1e-3 .. 3 u_y
    double next = d + std::copysign(std::min(std::abs(target - d), scale * u_y), target - d);
    if (unit(rng) < 0.1) next = d - (next - d);  // a sudden reversal
    h.push_back({d + 0.7 * (next - d), false});  // a Newton iterate that is not accepted
    h.push_back({next, true});
    d = next;
  }
  return h;
}

// Acceptance: a uniaxial orbit reproduces the 2D Bouc-Wen exactly. The biaxial scheme is the
// uniaxial one component for component (same branches, split points, sub-increments and
// trapezoidal roots), so the only differences are round-off (measured <= 2e-15 F_y over 20,000
// steps; asserted 1e-13).
TEST(CoupledBoucWen, UniaxialOrbitReproducesUniaxialBoucWen) {
  struct Shape {
    double n, beta, gamma;
  };
  for (const Shape s : {Shape{2, 0.5, 0.5}, Shape{2, 0.25, 0.75}, Shape{2, 0.75, 0.25},
                        Shape{1, 0.5, 0.5}, Shape{3, 0.3, 0.7}, Shape{2.5, 0.6, 0.4}}) {
    const BoucWenParameters p = thesis_bearing(s.n, s.beta, s.gamma);
    for (const double angle : {0.0, 0.5 * kPi, kPi / 6, -2.0}) {
      const Vector2d e(std::cos(angle), std::sin(angle));
      BoucWenMaterial uni(p);
      CoupledBoucWenMaterial bi(p);
      double worst_force = 0, worst_tangent = 0;
      for (const Trial& t : irregular_history(p.yield_displacement, 7)) {
        uni.set_trial(t.d);
        bi.set_trial(t.d * e, Vector2d::Zero());
        const Vector2d F = bi.force();
        worst_force = std::max(worst_force, (F - uni.force() * e).norm());
        // Along the orbit the tangent is the uniaxial one: e^T K e.
        worst_tangent = std::max(worst_tangent, std::abs(e.dot(bi.tangent() * e) - uni.tangent()));
        if (t.commit) {
          uni.commit();
          bi.commit();
        }
      }
      SCOPED_TRACE(testing::Message() << "n " << s.n << " beta " << s.beta << " angle " << angle);
      // Along an axis the arithmetic is nearly the uniaxial one; along an oblique line each
      // component carries its own rounding.
      EXPECT_LE(worst_force, 1e-13 * p.yield_force);  // measured <= 2e-15 F_y
      EXPECT_LE(worst_tangent, 1e-9 * p.elastic_stiffness);
    }
  }
}

// Radial push to r, then round the circle of radius r several times in small steps.
template <class Law>
void circular_orbit(Law& law, double r, int turns, double step_angle,
                    const std::function<void(double, const Law&)>& each) {
  const int radial = 50;
  for (int k = 1; k <= radial; ++k) {
    law.set_trial(Vector2d(r * k / radial, 0.0), Vector2d::Zero());
    law.commit();
    each(0.0, law);
  }
  const int n = static_cast<int>(std::round(2 * kPi * turns / step_angle));
  for (int k = 1; k <= n; ++k) {
    const double phi = k * step_angle;
    law.set_trial(Vector2d(r * std::cos(phi), r * std::sin(phi)), Vector2d::Zero());
    law.commit();
    each(phi, law);
  }
}

// Acceptance: on a circular orbit |z| <= 1 at all times and the force follows the circular
// yield surface. With r = 20 u_y the hysteretic force lags the direction of motion by an
// angle of order u_y/r: after the first quarter turn |z| stays within 1 % of 1 and z points
// along the velocity to within 0.1 rad.
TEST(CoupledBoucWen, CircularOrbitStaysInsideAndOnTheCircle) {
  const BoucWenParameters p = thesis_bearing();
  for (const double step : {0.002, 0.05}) {  // 0.04 u_y and 1 u_y of arc per step
    CoupledBoucWenMaterial law(p);
    const double r = 20 * p.yield_displacement;
    double max_z = 0, min_z_later = 2, max_lag = 0;
    circular_orbit<CoupledBoucWenMaterial>(law, r, 3, step, [&](double phi, const auto& m) {
      const Vector2d z = m.internal();
      max_z = std::max(max_z, z.norm());
      if (phi > 0.5 * kPi) {
        min_z_later = std::min(min_z_later, z.norm());
        const Vector2d velocity_dir(-std::sin(phi), std::cos(phi));
        max_lag = std::max(max_lag, std::acos(std::min(1.0, z.normalized().dot(velocity_dir))));
        // The force is the elastic part plus the hysteretic part on the circle of radius Q.
        const Vector2d hysteretic = m.force() - p.alpha * p.elastic_stiffness * m.deformation();
        EXPECT_NEAR(hysteretic.norm(), (1 - p.alpha) * p.yield_force,
                    0.01 * (1 - p.alpha) * p.yield_force);
      }
    });
    EXPECT_LE(max_z, 1.0 + 1e-12) << std::setprecision(17) << max_z - 1;
    EXPECT_GE(min_z_later, 0.99);
    EXPECT_LE(max_lag, 0.1);
  }
}

// The biaxial bilinear slides exactly on the circle |F_h| = (1-alpha) F_y.
TEST(BilinearBiaxial, CircularOrbitSlidesOnTheYieldCircle) {
  const BoucWenParameters p = thesis_bearing();
  BilinearBiaxialMaterial law(p.elastic_stiffness, p.alpha, p.yield_force);
  const double r = 20 * p.yield_displacement;
  const double f_h = (1 - p.alpha) * p.yield_force;
  circular_orbit<BilinearBiaxialMaterial>(law, r, 2, 0.01, [&](double phi, const auto& m) {
    const Vector2d hysteretic = m.force() - p.alpha * p.elastic_stiffness * m.deformation();
    EXPECT_LE(hysteretic.norm(), f_h * (1 + 1e-12));
    if (phi > 0) {
      EXPECT_NEAR(hysteretic.norm(), f_h, 1e-12 * f_h);
    }
  });
}

// Acceptance: the uncoupled law reaches the square's corner; the coupled one stays on the
// circle. Diagonal push to 30 u_y in both directions.
TEST(UncoupledBearing, DiagonalPushReachesTheCornerOfTheSquare) {
  const BoucWenParameters p = thesis_bearing();
  UncoupledBiaxialMaterial square(std::make_unique<BoucWenMaterial>(p),
                                  std::make_unique<BoucWenMaterial>(p));
  CoupledBoucWenMaterial circle(p);
  for (int k = 1; k <= 300; ++k) {
    const Vector2d d = Vector2d(1, 1) * (0.1 * k * p.yield_displacement);
    square.set_trial(d, Vector2d::Zero());
    circle.set_trial(d, Vector2d::Zero());
    square.commit();
    circle.commit();
  }
  // tanh(30) = 1 - 2e-26: both components saturate.
  EXPECT_NEAR(square.internal()[0], 1.0, 1e-9);
  EXPECT_NEAR(square.internal()[1], 1.0, 1e-9);
  EXPECT_NEAR(square.internal().norm(), std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(circle.internal()[0], 1.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(circle.internal()[1], 1.0 / std::sqrt(2.0), 1e-9);
}

// Central differences of the force over the deformation (and over the rate): relative error
// of the consistent tangent. The FD step 1e-7 u_y keeps truncation (~1e-14 relative) and
// round-off (~1e-16 F/(1e-7 u_y K) ~ 1e-9) far below the 1e-6 asserted.
template <class Law>
void expect_tangents_match_fd(Law& law, const Vector2d& d, const Vector2d& v, double u_y,
                              double k_scale, double c_scale) {
  law.set_trial(d, v);
  const Matrix2d K = law.tangent();
  const Matrix2d C = law.rate_tangent();
  Matrix2d K_fd, C_fd;
  const double h = 1e-7 * u_y;
  for (int j = 0; j < 2; ++j) {
    const Vector2d dj = Vector2d::Unit(j) * h;
    law.set_trial(d + dj, v);
    const Vector2d fp = law.force();
    law.set_trial(d - dj, v);
    K_fd.col(j) = (fp - law.force()) / (2 * h);
    const double hv = 1e-7 * std::max(v.norm(), 1e-3);
    const Vector2d vj = Vector2d::Unit(j) * hv;
    law.set_trial(d, v + vj);
    const Vector2d gp = law.force();
    law.set_trial(d, v - vj);
    C_fd.col(j) = (gp - law.force()) / (2 * hv);
  }
  law.set_trial(d, v);
  EXPECT_LE((K - K_fd).cwiseAbs().maxCoeff(), 1e-6 * k_scale) << "K\n" << K << "\nFD\n" << K_fd;
  EXPECT_LE((C - C_fd).cwiseAbs().maxCoeff(), 1e-6 * c_scale) << "C\n" << C << "\nFD\n" << C_fd;
}

// Committed states along a random 2D walk, then trial increments in random directions from
// 1e-3 u_y (inside one sub-increment) to 5 u_y (many sub-increments, components crossing 0).
TEST(CoupledBoucWen, ConsistentTangentMatchesFiniteDifferences) {
  for (const double n : {2.0, 3.0, 1.5}) {
    const BoucWenParameters p = thesis_bearing(n, 0.5, 0.5);
    CoupledBoucWenMaterial law(p);
    std::mt19937 rng(11);
    std::normal_distribution<double> g(0.0, 1.0);
    Vector2d d = Vector2d::Zero();
    bool off_diagonal_seen = false;
    for (int k = 0; k < 60; ++k) {
      const double size = p.yield_displacement * std::pow(10.0, -3.0 + 3.7 * (k % 7) / 6.0);
      const Vector2d trial = d + size * Vector2d(g(rng), g(rng)).normalized();
      expect_tangents_match_fd(law, trial, Vector2d::Zero(), p.yield_displacement,
                               p.elastic_stiffness, 1.0);
      const Matrix2d K = law.tangent();
      if (std::abs(K(0, 1) - K(1, 0)) > 1e-3 * p.elastic_stiffness) off_diagonal_seen = true;
      law.set_trial(trial, Vector2d::Zero());
      law.commit();
      d = trial;
    }
    EXPECT_TRUE(off_diagonal_seen) << "the walk never tested a non-symmetric tangent";
  }
}

// The n = 2 closed form (one sub-increment, written without |dx|) is the general path's scheme:
// z and dz/dx agree to round-off from states inside the disc, on its rim and beyond it, for
// increments in every direction up to the size where the closed form hands over.
TEST(CoupledBoucWen, ClosedFormStepMatchesTheGeneralPath) {
  const BoucWenParameters p = thesis_bearing(2.0, 0.5, 0.5);
  const CoupledBoucWenMaterial law(p);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 20000; ++k) {
    const double angle_z = 2.0 * kPi * unit(rng), angle_dx = 2.0 * kPi * unit(rng);
    const double radius = k % 3 == 0 ? 1.0 : k % 3 == 1 ? unit(rng) : 1.0 + 0.5 * unit(rng);
    const Vector2d z0 = radius * Vector2d(std::cos(angle_z), std::sin(angle_z));
    const double size = std::pow(10.0, -6.0 + 6.0 * unit(rng));  // 1e-6 .. 1 u_y
    const Vector2d dx = size * Vector2d(std::cos(angle_dx), std::sin(angle_dx));
    const CoupledBoucWenMaterial::ZUpdate fast = law.integrate(z0, dx);
    const CoupledBoucWenMaterial::ZUpdate general = law.integrate(z0, dx, false);
    // Round-off of two evaluation orders; dz/dx is O(1) (A = 1), but the general path's chain
    // rule multiplies de/dx = (I - e e^T)/l by l/2: its rounding grows as eps/l.
    EXPECT_LE((fast.z - general.z).cwiseAbs().maxCoeff(), 1e-13) << z0.transpose() << " / "
                                                                  << dx.transpose();
    EXPECT_LE((fast.dz_dx - general.dz_dx).cwiseAbs().maxCoeff(), 1e-12 + 1e-14 / size)
        << z0.transpose() << " / " << dx.transpose();
    compared += (fast.z - general.z).cwiseAbs().maxCoeff() > 0.0;
  }
  // The two paths did differ in rounding somewhere (so both were taken).
  EXPECT_GT(compared, 100);
}

TEST(BilinearBiaxial, ConsistentTangentMatchesFiniteDifferences) {
  const BoucWenParameters p = thesis_bearing();
  BilinearBiaxialMaterial law(p.elastic_stiffness, p.alpha, p.yield_force);
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  Vector2d d = Vector2d::Zero();
  for (int k = 0; k < 40; ++k) {
    const Vector2d trial = d + 2 * p.yield_displacement * Vector2d(g(rng), g(rng));
    expect_tangents_match_fd(law, trial, Vector2d::Zero(), p.yield_displacement,
                             p.elastic_stiffness, 1.0);
    law.set_trial(trial, Vector2d::Zero());
    law.commit();
    d = trial;
  }
}

FrictionPendulumParameters fp_parameters(bool smooth) {
  FrictionPendulumParameters p;
  p.weight = 1.27e6 / 16 * 9.81;
  p.radius = 2.0;
  p.mu_slow = 0.04;
  p.mu_fast = 0.10;
  p.rate_parameter = 30.0;
  p.yield_displacement = 5e-4;
  p.smooth = smooth;
  return p;
}

// Friction pendulum: tangent and the non-symmetric rate tangent W z (dmu/dv)^T by FD.
TEST(FrictionPendulum, TangentAndRateTangentMatchFiniteDifferences) {
  for (const bool smooth : {false, true}) {
    const FrictionPendulumParameters p = fp_parameters(smooth);
    FrictionPendulumMaterial law(p);
    std::mt19937 rng(3);
    std::normal_distribution<double> g(0.0, 1.0);
    Vector2d d = Vector2d::Zero();
    bool rate_coupling_seen = false;
    for (int k = 0; k < 40; ++k) {
      const Vector2d trial = d + 3 * p.yield_displacement * Vector2d(g(rng), g(rng));
      const Vector2d v = 0.05 * Vector2d(g(rng), g(rng));
      const double k_scale = p.mu_fast * p.weight / p.yield_displacement;
      const double c_scale = p.weight * (p.mu_fast - p.mu_slow) * p.rate_parameter;
      expect_tangents_match_fd(law, trial, v, p.yield_displacement, k_scale, c_scale);
      const Matrix2d C = law.rate_tangent();
      if (std::abs(C(0, 1) - C(1, 0)) > 1e-3 * c_scale) rate_coupling_seen = true;
      law.set_trial(trial, v);
      law.commit();
      d = trial;
    }
    EXPECT_TRUE(rate_coupling_seen);
  }
}

// Energy: over closed deformation loops the work done on the bearing minus the change of the
// stored energy (the dissipated energy) is >= 0, and for the bilinear law it equals the
// plastic work by hand. Work integrated with the trapezoidal rule over 2e-4 u_y steps.
template <class Law>
double dissipated_over_loops(Law& law, const std::function<Vector2d(double)>& path, int steps,
                             double energy_scale) {
  double work = 0.0;
  Vector2d d0 = path(0.0);
  law.set_trial(d0, Vector2d::Zero());
  law.commit();
  const double stored0 = law.stored_energy();
  Vector2d f0 = law.force();
  double min_dissipated = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const Vector2d d1 = path(static_cast<double>(k) / steps);
    law.set_trial(d1, Vector2d::Zero());
    law.commit();
    const Vector2d f1 = law.force();
    work += 0.5 * (f0 + f1).dot(d1 - d0);
    min_dissipated = std::min(min_dissipated, work - (law.stored_energy() - stored0));
    d0 = d1;
    f0 = f1;
  }
  // Never creates energy along the way (round-off: 1e-12 of F_y u_y).
  EXPECT_GE(min_dissipated, -1e-12 * energy_scale);
  return work - (law.stored_energy() - stored0);
}

TEST(BearingEnergy, WorkMinusStoredIsNonNegativeOverClosedLoops) {
  const BoucWenParameters p = thesis_bearing();
  const double u = p.yield_displacement;
  const std::vector<std::function<Vector2d(double)>> loops = {
      // circle through the origin, radius 10 u_y, twice
      [&](double s) -> Vector2d {
        return 10 * u * Vector2d(1 - std::cos(4 * kPi * s), std::sin(4 * kPi * s));
      },
      // figure eight, 15 u_y
      [&](double s) -> Vector2d {
        return 15 * u * Vector2d(std::sin(2 * kPi * s), std::sin(4 * kPi * s));
      },
      // small elastic-range ellipse, 0.3 u_y
      [&](double s) -> Vector2d {
        return 0.3 * u * Vector2d(std::sin(2 * kPi * s), 0.5 * std::sin(2 * kPi * s + 1));
      },
  };
  for (std::size_t i = 0; i < loops.size(); ++i) {
    SCOPED_TRACE(i);
    CoupledBoucWenMaterial coupled(p);
    EXPECT_GE(dissipated_over_loops(coupled, loops[i], 20000, p.yield_force * u),
              -1e-12 * p.yield_force * u);
    BilinearBiaxialMaterial bilinear(p.elastic_stiffness, p.alpha, p.yield_force);
    const double e_bl = dissipated_over_loops(bilinear, loops[i], 20000, p.yield_force * u);
    EXPECT_GE(e_bl, -1e-9 * p.yield_force * u);
    if (i == 2) {
      EXPECT_NEAR(e_bl, 0.0, 1e-9 * p.yield_force * u);  // elastic: nothing lost
    }
    UncoupledBiaxialMaterial uncoupled(std::make_unique<BoucWenMaterial>(p),
                                       std::make_unique<BoucWenMaterial>(p));
    EXPECT_GE(dissipated_over_loops(uncoupled, loops[i], 20000, p.yield_force * u),
              -1e-12 * p.yield_force * u);
    FrictionPendulumMaterial fp(fp_parameters(false));
    EXPECT_GE(dissipated_over_loops(fp, loops[i], 20000, p.yield_force * u),
              -1e-12 * p.yield_force * u);
  }
}

}  // namespace
}  // namespace isopound
