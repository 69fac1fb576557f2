// PolygonContact (3D slab pounding, THEORY §6) on small hand-built models: face-on reduction to
// the 2D Kelvin–Voigt contact, corner impact torque, Coulomb sliding, passivity, tangent, Newton.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "solver/core/analysis.h"
#include "solver/core/newmark.h"
#include "solver/elements/contact.h"
#include "solver/elements/polygon_contact.h"
#include "solver/materials/impact_law.h"
#include "tests/model_test_support.h"

namespace isopound {
namespace {

constexpr double kSlabMass = 340e3, kWallMass = 500e3, kSide = 10.0;

ConvexPolygon rectangle(double x0, double y0, double x1, double y1) {
  return ConvexPolygon{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A square slab of side kSide centred at the origin with DOFs (u, v, θ) = 3k, 3k+1, 3k+2.
PolygonBody slab(int first_dof, Vec2 centre = {0, 0}, bool with_theta = true) {
  const double a = 0.5 * kSide;
  return {first_dof,
          first_dof + 1,
          with_theta ? first_dof + 2 : -1,
          centre,
          rectangle(centre.x - a, centre.y - a, centre.x + a, centre.y + a),
          kSlabMass};
}

// A rigid wall whose face x = face_x looks towards −x, 1 m thick, 20 m long: never moves.
PolygonBody wall_at(double face_x) {
  return {-1, -1, -1, {0, 0}, rectangle(face_x, -10.0, face_x + 1.0, 10.0), kWallMass};
}

// The 2D Kelvin–Voigt law a face-on contact of the kSide-long slab reduces to: k = k_N L, the same
// e and masses.
ImpactLawConfig face_on_kelvin_voigt(const PolygonContactConfig& cfg) {
  ImpactLawConfig law;
  law.law = "kelvin_voigt";
  law.k = cfg.k_normal * kSide;
  law.e = cfg.restitution;
  law.mass_1 = kSlabMass;
  law.mass_2 = kWallMass;
  return law;
}

double polar_moment(double m) {
  return m * (kSide * kSide + kSide * kSide) / 12.0;
}

// A free square slab (3 DOFs) or its translational part (2 DOFs), no springs.
Model slab_model(bool with_theta, double kx = 0.0, double ky = 0.0, double ktheta = 0.0) {
  Model m;
  const int n = with_theta ? 3 : 2;
  m.dofs = {{"slab/x", 0, 0}, {"slab/y", 0, 0}};
  if (with_theta) m.dofs.push_back({"slab/theta", 0, 0});
  m.mass = Eigen::MatrixXd::Zero(n, n);
  m.stiffness = Eigen::MatrixXd::Zero(n, n);
  m.damping = Eigen::MatrixXd::Zero(n, n);
  m.mass(0, 0) = m.mass(1, 1) = kSlabMass;
  m.stiffness(0, 0) = kx;
  m.stiffness(1, 1) = ky;
  if (with_theta) {
    m.mass(2, 2) = polar_moment(kSlabMass);
    m.stiffness(2, 2) = ktheta;
  }
  m.influence = Eigen::VectorXd::Zero(n);
  m.influence[0] = 1.0;  // the ground acceleration acts along x
  return m;
}

// Fixed-step Newmark with the analysis driver's event protocol (tests must not depend on the
// driver's step-limit rules): an event inside a step → redo the step cut there with the status
// frozen, then settle (restart from equilibrium if a force jumped); an event at the start →
// settle at once. `on_step(stepper, h, t)` runs after each accepted step, before its settle.
struct FixedRun {
  long steps = 0, events = 0, halvings = 0;
  int max_iterations = 0;
  double mean_iterations = 0.0;
  std::vector<double> work;  // ∫ v·f_e dt per element (trapezoid, as run_analysis)
};

template <class OnStep>
FixedRun run_fixed(Model& model, double h, double t_end, double ag, const Eigen::VectorXd& u0,
                   const Eigen::VectorXd& v0, OnStep&& on_step) {
  NewmarkStepper stepper(model, {1e-9, 25});
  stepper.start(u0, v0, ag);
  const std::size_t ne = model.elements.size();
  FixedRun out;
  out.work.assign(ne, 0.0);
  std::vector<double> p_prev(ne), theta_e(ne);
  std::vector<char> settling(ne, 0);
  const auto powers = [&] {
    for (std::size_t k = 0; k < ne; ++k) p_prev[k] = model.elements[k]->power(stepper.v());
  };
  const auto settle = [&] {
    bool jumped = false;
    for (std::size_t k = 0; k < ne; ++k)
      if (settling[k]) jumped = model.elements[k]->settle_event() || jumped;
    if (jumped) stepper.restart(ag);
    powers();
  };
  powers();
  double t = 0.0, forced = 0.0, halved = 0.0;  // forced: a step cut at an event
  int settles_here = 0;
  long iterations = 0;
  while (t < t_end - 1e-9 * h) {
    const bool at_event = forced > 0;
    const double step = at_event ? forced : std::min(halved > 0 ? halved : h, t_end - t);
    const StepOutcome o = stepper.try_step(step, ag, !at_event && step == h, at_event);
    if (!o.converged) {  // halve, as run_analysis does
      stepper.reject();
      if (step < h * 1e-6) throw std::runtime_error("Newton failed at t = " + std::to_string(t));
      (at_event ? forced : halved) = 0.5 * step;
      ++out.halvings;
      continue;
    }
    iterations += o.iterations;
    out.max_iterations = std::max(out.max_iterations, o.iterations);
    if (!at_event) {
      double theta = 1.0;
      for (std::size_t k = 0; k < ne; ++k) {
        theta_e[k] = model.elements[k]->event_fraction();
        theta = std::min(theta, theta_e[k]);
      }
      if (theta < 1.0) {
        stepper.reject();
        ++out.events;
        for (std::size_t k = 0; k < ne; ++k)
          settling[k] = theta_e[k] <= std::max(theta * (1 + 1e-12), theta < 1e-4 ? 1e-4 : 0.0);
        if (theta < 1e-4) {
          settle();
          if (++settles_here > 4) throw std::runtime_error("events do not settle");
          continue;
        }
        forced = theta * step;
        continue;
      }
    }
    settles_here = 0;
    stepper.accept();
    ++out.steps;
    t += step;
    for (std::size_t k = 0; k < ne; ++k) {
      const double p = model.elements[k]->power(stepper.v());
      out.work[k] += 0.5 * step * (p_prev[k] + p);
      p_prev[k] = p;
    }
    on_step(stepper, step, t);
    if (at_event) settle();
    forced = halved = 0.0;
  }
  out.mean_iterations = double(iterations) / std::max(out.steps, 1L);
  return out;
}

double kinetic_energy(const Model& m, const Eigen::VectorXd& v) {
  return 0.5 * v.dot(m.mass * v);
}

TEST(PolygonContactStiffness, ConcreteGivesTheThesisValues) {
  // Thesis §5.5: E_st = 30 GPa, ν = 0.2 on both sides → k_N = 2.58e10 N/m², k_T = 5.74e9 N/m
  // (three significant digits as printed).
  const ContactStiffness k = contact_stiffness_from_materials(30e9, 0.2, 30e9, 0.2);
  EXPECT_NEAR(k.k_normal, 2.58e10, 0.005e10);
  EXPECT_NEAR(k.k_tangential, 5.74e9, 0.005e9);
  // Independently: E_dyn = 5.82·30^0.63 GPa; k_N = E_dyn/(2(1−ν²)), k_T = G_dyn/(2(2−ν)).
  const double e_dyn = 5.82 * std::pow(30.0, 0.63) * 1e9;
  EXPECT_NEAR(k.k_normal, e_dyn / (2 * (1 - 0.04)), 1e-6 * k.k_normal);
  EXPECT_NEAR(k.k_tangential, e_dyn / 2.4 / (2 * 1.8), 1e-6 * k.k_tangential);
  EXPECT_THROW(contact_stiffness_from_materials(-1, 0.2, 30e9, 0.2), std::invalid_argument);
  EXPECT_THROW(contact_stiffness_from_materials(30e9, 0.5, 30e9, 0.2), std::invalid_argument);
}

// Face-on: the overlap is the rectangle L × δ, so A_c = L δ, δ_N = δ and the contact is the 2D
// Kelvin–Voigt law with k = k_N L, c = 2ξ√(k m_eff). Same fixed step, same event protocol.
TEST(PolygonContactFaceOn, ReducesToKelvinVoigtContact1D) {
  const double gap = 0.05, v0 = 1.0, h = 1e-4, t_end = 0.12;
  const double kx = kSlabMass * std::pow(2 * std::numbers::pi / 2.0, 2);  // T_b = 2 s
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.keep_tension = true;  // Contact1D's Kelvin–Voigt keeps its tension

  Model m3 = slab_model(true, kx, kx, kx * polar_moment(1.0));
  m3.elements.push_back(
      std::make_unique<PolygonContact>("slab-wall", slab(0), wall_at(0.5 * kSide + gap), cfg));
  const auto* c3 = static_cast<const PolygonContact*>(m3.elements[0].get());

  Model m1;
  m1.dofs = {{"slab/x", 0, 0}};
  m1.mass = Eigen::MatrixXd::Constant(1, 1, kSlabMass);
  m1.stiffness = Eigen::MatrixXd::Constant(1, 1, kx);
  m1.damping = Eigen::MatrixXd::Zero(1, 1);
  m1.influence = Eigen::VectorXd::Ones(1);
  const ImpactLawConfig law = face_on_kelvin_voigt(cfg);
  m1.elements.push_back(std::make_unique<Contact1D>("slab-wall", ContactBody{0, 1.0}, ContactBody{},
                                                    gap, make_impact_law(law),
                                                    effective_mass(kSlabMass, kWallMass), 100));
  const auto* c1 = static_cast<const Contact1D*>(m1.elements[0].get());

  struct Peaks {
    double force = 0, pen = 0, u = 0, v_back = 0, theta = 0, uy = 0;
    std::vector<double> u_hist;
  };
  Peaks p3, p1;
  const auto r3 = run_fixed(m3, h, t_end, 0.0, Eigen::Vector3d::Zero(), Eigen::Vector3d(v0, 0, 0),
                            [&](const NewmarkStepper& s, double, double) {
                              p3.force = std::max(p3.force, c3->output(0));
                              p3.pen = std::max(p3.pen, c3->output(3));
                              p3.u = std::max(p3.u, s.u()[0]);
                              p3.v_back = std::min(p3.v_back, s.v()[0]);
                              p3.theta = std::max(p3.theta, std::abs(s.u()[2]));
                              p3.uy = std::max(p3.uy, std::abs(s.u()[1]));
                              p3.u_hist.push_back(s.u()[0]);
                            });
  const auto r1 =
      run_fixed(m1, h, t_end, 0.0, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Constant(1, v0),
                [&](const NewmarkStepper& s, double, double) {
                  p1.force = std::max(p1.force, c1->force());
                  p1.pen = std::max(p1.pen, c1->penetration());
                  p1.u = std::max(p1.u, s.u()[0]);
                  p1.v_back = std::min(p1.v_back, s.v()[0]);
                  p1.u_hist.push_back(s.u()[0]);
                });
  ASSERT_EQ(c3->impacts(), 1);
  ASSERT_EQ(c1->impacts(), 1);
  ASSERT_EQ(r3.steps, r1.steps);  // the same events, so the same step sequence
  EXPECT_GT(p1.force, 1e6);       // a real impact happened
  EXPECT_LT(p1.v_back, -0.3);     // and it rebounded
  const auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
  // Up to the separation both elements take identical steps and agree to 1e-6. Contact1D's
  // separation is now located with the interior-crossing witness of branch contact2d (tolerance
  // 0 at an end-of-step crossing, 1e-12 m inside), PolygonContact's with one witness call: at
  // this fixed 1e-4 s step (28 steps per contact) the rebound then differs by 0.3 %, a
  // discretisation difference of the separation cut (at default stepping the two agree to 3e-8,
  // PolygonContactFaceOn.RunAnalysisAtDefaultsAgreesWithContact1D). Making the two event rules
  // identical is left to issue 16; until then the approach and compression phase is compared step
  // by step at 1e-6 and the rebound to 1 %.
  EXPECT_LT(rel(p3.force, p1.force), 1e-6);
  EXPECT_LT(rel(p3.pen, p1.pen), 1e-6);
  EXPECT_LT(rel(p3.u, p1.u), 1e-6);
  EXPECT_LT(rel(p3.v_back, p1.v_back), 1e-2);
  EXPECT_LT(rel(c3->max_impact_velocity(), c1->max_impact_velocity()), 1e-6);
  // The separation: the first step after the peak penetration within 1 % of it from the wall.
  const std::size_t peak_step = static_cast<std::size_t>(
      std::max_element(p1.u_hist.begin(), p1.u_hist.end()) - p1.u_hist.begin());
  std::size_t separation_step = p1.u_hist.size();
  for (std::size_t i = peak_step; i < p1.u_hist.size(); ++i)
    if (p1.u_hist[i] - gap < 0.01 * (p1.u - gap)) {
      separation_step = i;
      break;
    }
  ASSERT_LT(separation_step, p1.u_hist.size());
  for (std::size_t i = 0; i < separation_step; ++i)
    ASSERT_NEAR(p3.u_hist[i], p1.u_hist[i], 1e-6 * p1.u) << "step " << i;
  // Doubly symmetric and pushed square-on: no rotation and no sideways motion (round-off).
  // (measured 5e-10 rad: a residual torque of ~2 N m, 1e-9 of F_N L; it moves the corners by
  // 3e-9 m, 5e-8 of the peak displacement).
  EXPECT_LT(p3.theta * 0.5 * kSide, 1e-6 * p1.u);
  EXPECT_LT(p3.uy, 1e-12);
  // Same damping: the effective mass and ξ(e) are those of the 2D law.
  EXPECT_DOUBLE_EQ(c3->effective_mass(), effective_mass(kSlabMass, kWallMass));
  EXPECT_DOUBLE_EQ(c3->normal_damping_ratio(), kelvin_voigt_xi(0.65));
}

// A slab turned +10° (counter-clockwise) moving +x hits the wall with its lower-right corner,
// below its centre O. The wall pushes it along −x there, so the torque about O is
// (p_WC − p_WO) × F = r_y·F_N < 0: clockwise, turning the slab back towards face-on.
TEST(PolygonContactCorner, TorqueTurnsTheSlabBackTowardsFaceOn) {
  const double theta0 = 10.0 * std::numbers::pi / 180.0, gap = 0.02;
  PolygonContactConfig cfg;
  cfg.friction = false;
  Model m = slab_model(true);
  const double reach = 0.5 * kSide * (std::cos(theta0) + std::sin(theta0));  // corner's x
  m.elements.push_back(std::make_unique<PolygonContact>("c", slab(0), wall_at(reach + gap), cfg));
  auto* c = static_cast<PolygonContact*>(m.elements[0].get());
  int contact_steps = 0;
  double min_torque = 0.0;
  run_fixed(m, 5e-5, 0.1, 0.0, Eigen::Vector3d(0, 0, theta0), Eigen::Vector3d(1.0, 0, 0),
            [&](const NewmarkStepper& s, double, double) {
              if (c->output(0) <= 0.0) return;  // open, or clamped (no tension)
              ++contact_steps;
              Eigen::VectorXd f = Eigen::VectorXd::Zero(3);
              c->add_force(f);
              const double torque_on_slab = -f[2];
              const ContactSnapshot snap = c->snapshot();
              const Vec2 r = snap.p_WC - Vec2{s.u()[0], s.u()[1]};
              EXPECT_LT(r.y, 0.0);
              EXPECT_LT(torque_on_slab, 0.0);
              // (p_WC − p_WO) × F with F = −F_N n_AB on the slab (A).
              EXPECT_NEAR(torque_on_slab, cross(r, -snap.normal_force * snap.n_AB),
                          1e-9 * std::abs(torque_on_slab) + 1e-6);
              min_torque = std::min(min_torque, torque_on_slab);
            });
  EXPECT_GT(contact_steps, 10);
  EXPECT_EQ(c->impacts(), 1);
  EXPECT_LT(min_torque, -1e5);
}

// Quasi-static sweeps through the triangle → quadrilateral transition: the normal and the
// elastic part k_N A_c move continuously (A_c is C¹ in the translation), only c_N may jump.
TEST(PolygonContactCorner, TriangleToQuadrilateralKeepsTheNormalContinuous) {
  PolygonContactConfig cfg;
  cfg.friction = false;
  // (a) A turned slab pushed into the flat wall: the chord lies on the wall face.
  // (b) Two turned slabs corner to corner: the chord crosses both bodies' edges.
  struct Case {
    double theta_a, theta_b;
    bool wall;
  };
  // (b): A's corner (6.41, −2.98) at θ = 0.35 enters B's left face 0.3 m above B's corner; the
  // quadrilateral starts when B's corner enters A, and the chord then turns.
  for (const Case& k : {Case{0.17, 0.0, true}, Case{0.35, 0.0, false}}) {
    PolygonBody b = k.wall ? wall_at(6.0) : slab(3, {11.42, 1.72});
    PolygonContact c("c", slab(0), b, cfg);
    c.begin_step(1e-3, false);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
    u[2] = k.theta_a;
    u[5] = k.theta_b;
    int transitions = 0, prev_count = 0, after = 0;
    Vec2 prev_n{};
    double prev_area = 0.0, max_dn = 0.0, dn_at_transition = 0.0;
    const double du = 1e-4;
    for (int i = 0; i < 40000; ++i) {
      u[0] = i * du;
      c.set_trial(u, v);
      const ContactSnapshot s = c.snapshot();
      if (!s.in_contact) continue;
      const Overlap ov = overlap_of(slab(0).shape.placed({u[0], 0, u[2]}),
                                    b.shape.placed({u[3], u[4], u[5]}, b.p_WO));
      if (prev_count > 0) {
        const double dn = std::hypot(s.n_AB.x - prev_n.x, s.n_AB.y - prev_n.y);
        if (ov.vertex_count != prev_count && prev_count == 3 && ov.vertex_count == 4) {
          ++transitions;
          dn_at_transition = dn;
        } else {
          max_dn = std::max(max_dn, dn);
        }
        // k_N A_c changes by about its slope × du: no jump (|dA| ≤ w du, w ≤ 15 m here).
        EXPECT_LT(std::abs(s.area - prev_area), 15.0 * du * 1.01);
      }
      prev_count = ov.vertex_count;
      prev_n = s.n_AB;
      prev_area = s.area;
      if (transitions == 1 && ++after > 2000) break;
    }
    ASSERT_EQ(transitions, 1) << "no triangle → quadrilateral transition in the sweep";
    // Across the transition the normal turns no more than elsewhere in the sweep (plus
    // round-off): for the flat wall it does not turn at all.
    EXPECT_LE(dn_at_transition, std::max(2.0 * max_dn, 1e-12));
    if (k.wall) {
      EXPECT_LT(max_dn, 1e-10);
    }
  }
}

// Pressed against a wall by a constant ground acceleration and given a sideways velocity, the
// slab slides with |F_T| = μ_k F_N and stops after v0/(μ_k a) (F_N = m a at equilibrium);
// the friction-dissipated energy is the kinetic energy lost.
TEST(PolygonContactFriction, SlidingSlabHasKineticFrictionAndDissipates) {
  const double gap = 0.01, a_press = 2.0, v0 = 0.5;
  PolygonContactConfig cfg;
  Model m = slab_model(false);
  m.elements.push_back(std::make_unique<PolygonContact>("c", slab(0, {0, 0}, false),
                                                        wall_at(0.5 * kSide + gap), cfg));
  const auto* c = static_cast<const PolygonContact*>(m.elements[0].get());
  const double f_n = kSlabMass * a_press;
  const double delta_eq = f_n / (cfg.k_normal * kSide);
  int slip_steps = 0;
  double t_stop = -1.0, max_ratio_error = 0.0;
  run_fixed(m, 1e-4, 0.6, -a_press, Eigen::Vector2d(gap + delta_eq, 0.0), Eigen::Vector2d(0.0, v0),
            [&](const NewmarkStepper& s, double, double t) {
              // Slipping, still sliding along +y (at the reversal the dashpot may lower |F_T|
              // below μ_k F_N: it is bounded, not fixed, see THEORY-notes).
              if (c->output(6) == 1.0 && s.v()[1] > 0.0) {
                ++slip_steps;
                max_ratio_error =
                    std::max(max_ratio_error,
                             std::abs(std::abs(c->output(1)) - cfg.mu_kinetic * c->output(0)) /
                                 c->output(0));
              }
              if (t_stop < 0 && s.v()[1] <= 0.0) t_stop = t;
            });
  EXPECT_GT(slip_steps, 3000);
  EXPECT_LT(max_ratio_error, 1e-12);
  const double t_expected = v0 / (cfg.mu_kinetic * a_press);
  EXPECT_NEAR(t_stop, t_expected, 0.01 * t_expected);
  const double kinetic = 0.5 * kSlabMass * v0 * v0;
  EXPECT_GT(c->friction_dissipated(), 0.0);
  // Lost to sliding ≈ the kinetic energy (the tangential spring keeps μ_k F_N²/(2 k_T) ≈ 14 J
  // and the rebound on it is damped: within 2 %).
  EXPECT_NEAR(c->friction_dissipated(), kinetic, 0.02 * kinetic);
}

// Passivity: over every contact episode the contact takes energy out of the bodies. Free
// bodies (no springs or dampers), so the bodies' kinetic energy changes only by the contact's
// work; Newmark's average acceleration makes that change the exact discrete work.
TEST(PolygonContactPassivity, RandomObliqueImpactsWithFrictionNeverAddEnergy) {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int episodes = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const bool two_slabs = trial % 3 == 2;
    PolygonContactConfig cfg;
    cfg.mu_static = 0.3 + 0.6 * uni(rng);
    cfg.mu_kinetic = cfg.mu_static * (0.5 + 0.5 * uni(rng));
    cfg.restitution = 0.4 + 0.6 * uni(rng);
    const double theta0 = (uni(rng) - 0.5) * 0.8;
    Model m = slab_model(true);
    Eigen::VectorXd u0 = Eigen::VectorXd::Zero(3), v0(3);
    v0 << 0.3 + 1.7 * uni(rng), (uni(rng) - 0.5) * 2.0, (uni(rng) - 0.5) * 0.4;
    u0[2] = theta0;
    PolygonBody other =
        wall_at(0.5 * kSide * (std::abs(std::cos(theta0)) + std::abs(std::sin(theta0))) + 0.01);
    if (two_slabs) {
      // A second free slab to the right, turned, at rest: slab to slab.
      m.grow(6);
      m.dofs.resize(6, {"other", 1, 0});
      m.mass(3, 3) = m.mass(4, 4) = kSlabMass;
      m.mass(5, 5) = polar_moment(kSlabMass);
      const double theta_b = (uni(rng) - 0.5) * 0.8;
      const auto reach = [](double t) {
        return 0.5 * kSide * (std::abs(std::cos(t)) + std::abs(std::sin(t)));
      };
      other = slab(3, {reach(theta0) + reach(theta_b) + 0.02, (uni(rng) - 0.5) * 4.0});
      u0.conservativeResize(6);
      v0.conservativeResize(6);
      u0.tail(3) << 0.0, 0.0, theta_b;
      v0.tail(3).setZero();
    }
    m.elements.push_back(std::make_unique<PolygonContact>("c", slab(0), other, cfg));
    const auto* c = static_cast<const PolygonContact*>(m.elements[0].get());
    bool in_contact = false;
    double ke_start = kinetic_energy(m, v0), ke_onset = 0.0;
    // Slab to slab: momentum about the origin, each slab's mass at its DOF origin O' (its centre).
    const Vec2 o_b = other.p_WO;
    const auto momenta = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
      Eigen::Vector3d p = Eigen::Vector3d::Zero();  // P_x, P_y, L_z
      for (int k = 0; k < (two_slabs ? 2 : 1); ++k) {
        const Vec2 o = (k == 0 ? Vec2{0, 0} : o_b) + Vec2{u[3 * k], u[3 * k + 1]};
        p[0] += kSlabMass * v[3 * k];
        p[1] += kSlabMass * v[3 * k + 1];
        p[2] +=
            kSlabMass * cross(o, {v[3 * k], v[3 * k + 1]}) + polar_moment(kSlabMass) * v[3 * k + 2];
      }
      return p;
    };
    const Eigen::Vector3d p_start = momenta(u0, v0);
    Eigen::Vector3d p_end = p_start;
    run_fixed(m, 1e-4, two_slabs ? 0.6 : 0.3, 0.0, u0, v0,
              [&](const NewmarkStepper& s, double, double) {
                p_end = momenta(s.u(), s.v());
                const bool now = c->output(11) == 1.0;
                const double ke = kinetic_energy(m, s.v());
                if (!in_contact && now) ke_onset = ke;
                if (in_contact && !now) {
                  ++episodes;
                  // Net work of the contact on the bodies over the episode ≤ 0, up to the Newton
                  // residual tolerance (1e-9 m g ≈ 3e-3 N per DOF: free flight drifts by ~1e-12 KE
                  // per 100 steps).
                  EXPECT_LE(ke - ke_onset, 1e-9 * ke_start) << "trial " << trial;
                }
                in_contact = now;
                // (Between episodes the bodies fly freely; Newton's residual tolerance lets their
                // kinetic energy drift by ~2e-13 per step, which is why the check is per episode.)
              });
    EXPECT_GE(c->friction_dissipated(), 0.0);
    EXPECT_GE(c->output(10), -1e-9 * ke_start) << "impact-dissipated energy, trial " << trial;
    if (two_slabs) {
      // Equal and opposite forces: linear momentum is kept exactly by Newmark (to the Newton
      // tolerance); with the torques (p_WC − p_WO') × F about each moving origin, angular
      // momentum about a fixed point is kept up to the O(h²) of the trapezoidal rule (a wrong
      // lever arm or sign would change it by ~F_N·(lever)·T_c ~ 10⁵ kg m²/s).
      const double p_scale = kSlabMass * v0.head(2).norm();
      EXPECT_NEAR(p_end[0], p_start[0], 1e-9 * p_scale) << "trial " << trial;
      EXPECT_NEAR(p_end[1], p_start[1], 1e-9 * p_scale) << "trial " << trial;
      EXPECT_NEAR(p_end[2], p_start[2], 1e-4 * p_scale * kSide) << "trial " << trial;
    }
  }
  EXPECT_GE(episodes, 14);
}

// The tangent is the derivative of the force actually applied (return map included): compare
// add_tangent with central differences of add_force through set_trial, at stick, slip and
// frictionless states, slab to slab with all six DOFs.
TEST(PolygonContactTangent, MatchesFiniteDifferencesOfTheForce) {
  const double h = 1e-3, vf = 2.0 / h;
  struct Case {
    bool friction;
    double slide;  // tangential displacement in the step, m (large → slip)
  };
  for (const Case& k : {Case{false, 0.0}, Case{true, 1e-6}, Case{true, 2e-2}}) {
    PolygonContactConfig cfg;
    cfg.friction = k.friction;
    // A shallow, slightly skewed overlap (depth ~2e-4 m over 8 m): F_N ~ 1e8 N, so a 2 cm
    // slide exceeds μ_s F_N / k_T.
    PolygonContact c("c", slab(0), slab(3, {kSide + 0.0398, 2.0}), cfg);
    Eigen::VectorXd u(6), v(6);
    // Committed: in contact (an accepted step into the overlap), then a trial step on.
    u << 0.03, 0.0, 2e-5, -0.01, 0.0, -3e-5;
    v << 0.5, 0.1, 0.02, -0.2, 0.05, -0.01;
    c.begin_step(h, false);
    c.set_trial(u, v);
    ASSERT_EQ(c.output(11), 1.0);
    c.commit();
    u[1] += k.slide;
    u[0] += 1e-5;
    c.begin_step(h, false);
    c.set_trial(u, v);
    ASSERT_EQ(c.output(11), 1.0);
    if (k.friction) {
      EXPECT_EQ(c.output(6), k.slide > 1e-3 ? 1.0 : 0.0) << "stick/slip state";
    }
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
    c.add_tangent(K, vf);
    Eigen::MatrixXd fd(6, 6);
    for (int j = 0; j < 6; ++j) {
      const double eps = j % 3 == 2 ? 3e-9 : 3e-8;
      Eigen::VectorXd fp = Eigen::VectorXd::Zero(6), fm = Eigen::VectorXd::Zero(6);
      Eigen::VectorXd up = u, um = u, vp = v, vm = v;
      up[j] += eps;
      um[j] -= eps;
      vp[j] += vf * eps;
      vm[j] -= vf * eps;
      c.set_trial(up, vp);
      c.add_force(fp);
      c.set_trial(um, vm);
      c.add_force(fm);
      fd.col(j) = (fp - fm) / (2 * eps);
    }
    c.set_trial(u, v);
    // Two central differences with different steps: agree to ~1e-6 of the largest entry.
    EXPECT_LT((K - fd).cwiseAbs().maxCoeff(), 1e-6 * K.cwiseAbs().maxCoeff())
        << "friction " << k.friction << " slide " << k.slide << "\nK =\n"
        << K << "\nFD =\n"
        << fd;
    if (k.friction) {
      EXPECT_FALSE(c.symmetric_tangent());
    }
  }
}

// The stiffness product of the error estimate (one difference along x) against add_tangent's
// columns (velocity factor 0) times x, at stick, slip and frictionless states: the same to the
// differences' truncation error; an open contact adds nothing.
TEST(PolygonContactTangent, StiffnessProductMatchesTheTangentTimesX) {
  const double h = 1e-3;
  struct Case {
    bool friction;
    double slide;
  };
  for (const Case& k : {Case{false, 0.0}, Case{true, 1e-6}, Case{true, 2e-2}}) {
    PolygonContactConfig cfg;
    cfg.friction = k.friction;
    PolygonContact c("c", slab(0), slab(3, {kSide + 0.0398, 2.0}), cfg);
    ASSERT_TRUE(c.has_stiffness_product());
    Eigen::VectorXd u(6), v(6);
    u << 0.03, 0.0, 2e-5, -0.01, 0.0, -3e-5;
    v << 0.5, 0.1, 0.02, -0.2, 0.05, -0.01;
    c.begin_step(h, false);
    c.set_trial(u, v);
    c.commit();
    u[1] += k.slide;
    u[0] += 1e-5;
    c.begin_step(h, false);
    c.set_trial(u, v);
    ASSERT_EQ(c.output(11), 1.0);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
    c.add_tangent(K, 0.0);
    // An error-estimate-like x: displacements of a few nm, a rotation of ~1e-10 rad.
    Eigen::VectorXd x(6);
    x << 3e-9, -1e-9, 2e-10, -2e-9, 4e-9, -1e-10;
    const Eigen::VectorXd expected = K * x;
    Eigen::VectorXd y = Eigen::VectorXd::Constant(6, 1.0);
    c.add_stiffness_product(x, y);
    y.array() -= 1.0;
    // k_N w ~ 2.6e11 N/m times nm: ~1e3 N; a wrong sign or a missing DOF is off by ~100 %.
    EXPECT_LT((y - expected).cwiseAbs().maxCoeff(), 1e-5 * expected.cwiseAbs().maxCoeff())
        << "friction " << k.friction << " slide " << k.slide << "\nK x = " << expected.transpose()
        << "\nproduct = " << y.transpose();
  }
  // Open: nothing added.
  PolygonContact open("c", slab(0), slab(3, {kSide + 1.0, 2.0}), PolygonContactConfig{});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6);
  open.begin_step(h, false);
  open.set_trial(u, v);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(6);
  open.add_stiffness_product(Eigen::VectorXd::Constant(6, 1e-9), y);
  EXPECT_EQ(y.cwiseAbs().maxCoeff(), 0.0);
}

// The tangent by forward-mode differentiation (the default) against central differences of the
// force law (analytic_tangent: false) at 200 random closed states: slab to slab (six DOFs) and a
// turned slab on a fixed wall (three), triangles and quadrilaterals, stick, slip (from stick and
// frozen, continuous_force on and off), frictionless, approaching and receding. Equal to the
// differences' truncation and round-off, ~1e-7 of the largest entry (a missed term, e.g. C's
// motion or the friction's rotation, is ~1e-3 to 1); the stiffness product likewise.
TEST(PolygonContactTangent, DifferentiatedEqualsTheCentralDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int analytic = 0, slipping = 0, compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    PolygonContactConfig cfg;
    cfg.friction = trial % 5 != 0;
    cfg.continuous_force = trial % 3 == 0;
    const bool on_wall = trial % 2 == 0;
    const double theta = on_wall ? 0.3 * unit(rng) : 0.0;
    const double depth = 0.002 + 0.01 * std::abs(unit(rng));
    // Reach of the slab along +x at its turn: the wall's face at that minus the depth.
    const double reach = 0.5 * kSide * (std::abs(std::cos(theta)) + std::abs(std::sin(theta)));
    const PolygonBody a = slab(0);
    const PolygonBody b =
        on_wall ? wall_at(reach - depth) : slab(3, {kSide - depth, 3.0 * unit(rng)});
    PolygonContactConfig differences = cfg;
    differences.analytic_tangent = false;
    PolygonContact exact("c", a, b, cfg), reference("c", a, b, differences);
    const int n = on_wall ? 3 : 6;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v(n);
    u[2] = theta;
    for (int k = 0; k < n; ++k) v[k] = 0.3 * unit(rng) * (k % 3 == 2 ? 0.1 : 1.0);
    const double h = 1e-4, vf = 2.0 / h;
    for (PolygonContact* c : {&exact, &reference}) {
      c->begin_step(h, false);
      c->set_trial(u, v);
      c->commit();
    }
    // The trial: slid along the contact (slip when large) and turned a little.
    Eigen::VectorXd u1 = u;
    u1[1] += (trial % 4 == 0 ? 0.03 : 1e-6) * unit(rng);
    u1[0] += 1e-4 * unit(rng);
    u1[2] += 1e-4 * unit(rng);
    for (PolygonContact* c : {&exact, &reference}) {
      c->begin_step(h, trial % 7 == 0);
      c->set_trial(u1, v);
    }
    ASSERT_EQ(exact.output(0), reference.output(0));
    if (!exact.trial_closed()) continue;
    // Away from a switch (stick/slip, clamp, topology): the differences would straddle it.
    bool near_switch = false;
    const double status = exact.output(6);
    const bool differentiated = exact.trial_tangent_analytic();
    for (int j = 0; j < n && !near_switch; ++j)
      for (const double sign : {-1.0, 1.0}) {
        Eigen::VectorXd up = u1, vp = v;
        up[j] += sign * 2e-7;
        vp[j] += sign * 2e-7 * vf;
        exact.set_trial(up, vp);
        near_switch = near_switch || exact.output(6) != status ||
                      exact.trial_tangent_analytic() != differentiated;
      }
    exact.set_trial(u1, v);
    if (near_switch) continue;
    ++compared;
    analytic += exact.trial_tangent_analytic();
    slipping += exact.output(6) == 1.0;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), K_ref = Eigen::MatrixXd::Zero(n, n);
    exact.add_tangent(K, vf);
    reference.add_tangent(K_ref, vf);
    EXPECT_LT((K - K_ref).cwiseAbs().maxCoeff(), 2e-7 * K_ref.cwiseAbs().maxCoeff())
        << "trial " << trial << "\nK =\n"
        << K << "\ndifferences =\n"
        << K_ref;
    Eigen::VectorXd x(n);
    for (int k = 0; k < n; ++k) x[k] = 3e-9 * unit(rng) * (k % 3 == 2 ? 0.1 : 1.0);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(n), y_ref = Eigen::VectorXd::Zero(n);
    exact.add_stiffness_product(x, y);
    reference.add_stiffness_product(x, y_ref);
    EXPECT_LT((y - y_ref).cwiseAbs().maxCoeff(), 1e-5 * y_ref.cwiseAbs().maxCoeff())
        << "trial " << trial;
  }
  EXPECT_GE(compared, 150);
  EXPECT_GE(analytic, 140);
  EXPECT_GE(slipping, 20);
}

TEST(PolygonContactTangent, FaceOnMatchesTheAnalyticKelvinVoigtStiffness) {
  // Face-on: F = k_N L δ + c δ̇, so dF/du + vf dF/dv = k_N L + vf c with c = 2ξ√(k_N L m_eff).
  PolygonContactConfig cfg;
  cfg.friction = false;
  PolygonContact c("c", slab(0), wall_at(5.01), cfg);
  Eigen::VectorXd u = Eigen::Vector3d(0.013, 0.0, 0.0), v = Eigen::Vector3d(0.4, 0.0, 0.0);
  const double vf = 2.0 / 1e-4;
  c.begin_step(1e-4, false);
  c.set_trial(u, v);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
  c.add_tangent(K, vf);
  const double k = cfg.k_normal * kSide;
  const double damping =
      2 * kelvin_voigt_xi(cfg.restitution) * std::sqrt(k * effective_mass(kSlabMass, kWallMass));
  EXPECT_NEAR(K(0, 0), k + vf * damping, 1e-7 * (k + vf * damping));
  EXPECT_NEAR(c.output(0), k * 0.003 + damping * 0.4, 1e-9 * c.output(0));
}

// A closed form with a triangle: a slab turned π/4 pushes its corner d into the wall, so
// A_c = d², w = 2d, δ_N = 2A_c/w = d and F_N = k_N d² + 2ξ √(k_N d m_eff) ḋ. Slipping along the
// wall (the slab slid +y since the committed state), F_T = μ_k F_N: the tangent's x column is
// dF_N/du + vf dF_N/dv on x and μ_k times it on y.
TEST(PolygonContactTangent, CornerSlipMatchesTheClosedForm) {
  PolygonContactConfig cfg;
  const double theta = std::numbers::pi / 4, d = 0.01, rate = 0.3, vf = 2.0 / 1e-4;
  const double reach = 0.5 * kSide * std::sqrt(2.0);
  PolygonContact c("c", slab(0), wall_at(reach), cfg);
  Eigen::VectorXd u = Eigen::Vector3d(d, 0.0, theta), v = Eigen::Vector3d(rate, 0.1, 0.0);
  c.begin_step(1e-4, false);
  c.set_trial(u, v);
  c.commit();
  u[1] = 0.05;
  c.set_trial(u, v);
  ASSERT_EQ(c.output(6), 1.0);  // slipping
  const double m_eff = effective_mass(kSlabMass, kWallMass);
  const double xi = kelvin_voigt_xi(cfg.restitution);
  const double f_n = cfg.k_normal * d * d + 2 * xi * std::sqrt(cfg.k_normal * d * m_eff) * rate;
  EXPECT_NEAR(c.output(0), f_n, 1e-9 * f_n);
  EXPECT_NEAR(c.output(1), -cfg.mu_kinetic * f_n, 1e-9 * f_n);  // opposes the +y slide of A
  const double df_du = 2 * cfg.k_normal * d + xi * std::sqrt(cfg.k_normal * m_eff / d) * rate;
  const double df_dv = 2 * xi * std::sqrt(cfg.k_normal * d * m_eff);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3, 3);
  c.add_tangent(K, vf);
  EXPECT_NEAR(K(0, 0), df_du + vf * df_dv, 1e-6 * (df_du + vf * df_dv));
  EXPECT_NEAR(K(1, 0), cfg.mu_kinetic * (df_du + vf * df_dv), 1e-6 * (df_du + vf * df_dv));
}

// A slab corner (turned 45 degrees) pressed d = 1 cm into a wall and committed in stick with its
// spring at 0: committed apart at the same turn first, so that the onset slides nothing.
PolygonContact corner_in_stick(const PolygonContactConfig& cfg, Eigen::VectorXd& u,
                               const Eigen::VectorXd& v, double h) {
  const double theta = std::numbers::pi / 4, d = 0.01;
  PolygonContact c("c", slab(0), wall_at(0.5 * kSide * std::sqrt(2.0)), cfg);
  u = Eigen::Vector3d(-d, 0.0, theta);
  c.begin_step(h, false);
  c.set_trial(u, v);
  c.commit();  // apart, turned
  u[0] = d;
  c.set_trial(u, v);
  c.commit();  // stick, F_T = 0
  return c;
}

// PolygonContactConfig::continuous_force (struck columns' massless nodes): a trial's
// tangential force is continuous in the placement. A slab corner on a wall, committed in stick,
// slid along the wall: by default F_T drops from mu_s F_N to mu_k F_N where the trial starts to
// slip, continuous it stays at mu_s F_N (until the located event settles the drop). Committed in
// slip, a frozen trial whose f_tr turns: by default F_T = mu_k F_N sign(f_tr) flips by 2 mu_k F_N,
// continuous it sticks (F_T = f_tr) in between. The largest change of F_T between neighbouring
// samples against the jump the default has (the spring's own change per sample is ~1e-3 of it).
TEST(PolygonContactFriction, ContinuousFrictionHasNoJumpInATrial) {
  const double h = 1e-4;
  const auto largest_jump = [&](bool continuous, bool from_slip, double& f_n) {
    PolygonContactConfig cfg;
    cfg.continuous_force = continuous;
    Eigen::VectorXd u, v = Eigen::Vector3d(0.0, 0.0, 0.0);
    PolygonContact c = corner_in_stick(cfg, u, v, h);
    if (from_slip) {
      u[1] = 0.05;
      c.set_trial(u, v);
      c.commit();  // slipping (settled as the event would be: the trial's status committed)
      c.begin_step(h, true);
    }
    f_n = c.output(0);
    double jump = 0.0, previous = 0.0;
    for (int i = 0; i <= 20000; ++i) {
      if (from_slip)
        v[1] = -2.0 + 2e-4 * i;  // f_tr = s_C + c_T rate_t turns
      else
        u[1] = 5e-8 * i;  // s_tr = k_T u climbs through mu_s F_N
      c.set_trial(u, v);
      if (i > 0) jump = std::max(jump, std::abs(c.output(1) - previous));
      previous = c.output(1);
    }
    return jump;
  };
  PolygonContactConfig cfg;
  double f_n = 0.0;
  const double drop_default = largest_jump(false, false, f_n);
  const double drop = (cfg.mu_static - cfg.mu_kinetic) * f_n;
  const double drop_continuous = largest_jump(true, false, f_n);
  const double flip_default = largest_jump(false, true, f_n);
  const double flip = 2 * cfg.mu_kinetic * f_n;
  const double flip_continuous = largest_jump(true, true, f_n);
  std::printf(
      "[friction] largest change per sample: stick->slip %.4g (default %.4g, drop %.4g), "
      "frozen slip %.4g (default %.4g, flip %.4g) N\n",
      drop_continuous, drop_default, drop, flip_continuous, flip_default, flip);
  EXPECT_GT(drop_default, 0.9 * drop);
  EXPECT_LT(drop_continuous, 1e-2 * drop);
  EXPECT_GT(flip_default, 0.9 * flip);
  EXPECT_LT(flip_continuous, 1e-2 * flip);
}

// continuous_force, the shallow overlap's shape: a slab corner (a triangular overlap, w = 2 x
// depth) approaching a wall at 0.3 m/s, pressed through the sliver's depth. By default the shape
// (w, n, C) of an overlap shallower than the sliver is that of one a sliver deeper, so c_N ∝ √w
// jumps where the overlap reaches the sliver's depth; continuous, it is that of an overlap as
// deep as the sliver, the same shape there. The largest change of F_N between neighbouring
// samples against the default's.
TEST(PolygonContactShape, ContinuousForceHasNoJumpAtTheSliversDepth) {
  const double theta = std::numbers::pi / 4, rate = 0.3;
  const double reach = 0.5 * kSide * std::sqrt(2.0);
  const auto largest_jump = [&](bool continuous) {
    PolygonContactConfig cfg;
    cfg.friction = false;
    cfg.continuous_force = continuous;
    PolygonContact c("c", slab(0), wall_at(reach), cfg);
    c.begin_step(1e-4, false);
    double jump = 0.0, previous = 0.0;
    for (int i = 1; i <= 4000; ++i) {
      // depths 1e-10 .. 4e-7 m: the sliver is 1e-8 of the slab's size, 1e-7 m
      const Eigen::VectorXd u = Eigen::Vector3d(1e-10 * i, 0.0, theta);
      c.set_trial(u, Eigen::Vector3d(rate, 0.0, 0.0));
      if (i > 1) jump = std::max(jump, std::abs(c.output(0) - previous));
      previous = c.output(0);
    }
    return jump;
  };
  const double jump_default = largest_jump(false), jump = largest_jump(true);
  std::printf("[shape] largest change of F_N per 1e-10 m: %.4g N (default %.4g N)\n", jump,
              jump_default);
  EXPECT_LT(jump, 0.05 * jump_default);
}

// The friction status forced (a caller solving by the two smooth branches): stick keeps
// F_T = f_tr beyond the limit, slip gives mu F_N where the return map sticks; kFree the law.
TEST(PolygonContactFriction, ForcedStatusGivesEachSmoothBranch) {
  PolygonContactConfig cfg;
  Eigen::VectorXd u, v = Eigen::Vector3d(0.0, 0.0, 0.0);
  PolygonContact c = corner_in_stick(cfg, u, v, 1e-4);
  u[1] = 1e-3;  // s_tr = k_T * ~1e-3 m, several times mu_s F_N
  c.set_trial(u, v);
  const double f_n = c.output(0), slip = std::abs(c.output(1));
  ASSERT_EQ(c.output(6), 1.0);
  EXPECT_NEAR(slip, cfg.mu_kinetic * f_n, 1e-9 * f_n);
  c.force_friction_status(PolygonContact::FrictionStatus::kStick);
  c.set_trial(u, v);
  EXPECT_EQ(c.output(6), 0.0);
  EXPECT_GT(std::abs(c.output(1)), 2 * cfg.mu_static * f_n);
  u[1] = 1e-6;  // the return map sticks here
  c.force_friction_status(PolygonContact::FrictionStatus::kSlip);
  c.set_trial(u, v);
  EXPECT_EQ(c.output(6), 1.0);
  EXPECT_NEAR(std::abs(c.output(1)), cfg.mu_kinetic * c.output(0), 1e-9 * f_n);
  c.force_friction_status(PolygonContact::FrictionStatus::kFree);
  c.set_trial(u, v);
  EXPECT_EQ(c.output(6), 0.0);
  EXPECT_LT(std::abs(c.output(1)), cfg.mu_kinetic * c.output(0));
}

// Newton on a static problem K u + f_e(u) = p with the element's tangent and an LU solve (the
// tangent is non-symmetric): a slab on springs pushed obliquely into a wall, friction slipping.
// Quadratic convergence: each residual at most C × the previous one squared, few iterations.
TEST(PolygonContactTangent, NewtonConvergesQuadratically) {
  PolygonContactConfig cfg;
  const double k_spring = 1e8;
  for (const double push_y : {1e5, 6e6}) {  // sticks (< μ_s F_N = 4e6 N), slips
    PolygonContact c("c", slab(0), wall_at(5.0), cfg);
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
    K(0, 0) = K(1, 1) = k_spring;
    K(2, 2) = k_spring * 25.0;
    const Eigen::Vector3d p(5e6, push_y, 1e5);
    Eigen::VectorXd u = Eigen::Vector3d(1e-3, 0.0, 0.0), v = Eigen::Vector3d::Zero();
    std::vector<double> residuals;
    c.begin_step(1.0, false);
    for (int it = 0; it < 30; ++it) {
      c.set_trial(u, v);
      Eigen::VectorXd r = K * u - p;
      c.add_force(r);
      residuals.push_back(r.cwiseAbs().maxCoeff());
      if (residuals.back() < 1e-9 * p.cwiseAbs().maxCoeff()) break;
      Eigen::MatrixXd J = K;
      c.add_tangent(J, 0.0);
      u -= J.partialPivLu().solve(r);
    }
    ASSERT_LT(residuals.back(), 1e-9 * p.cwiseAbs().maxCoeff());
    EXPECT_LE(residuals.size(), 9u) << "push_y " << push_y;
    EXPECT_EQ(c.output(6), push_y > 1e6 ? 1.0 : 0.0) << "push_y " << push_y;
    // Once close (r < 1e-3 of the load), r_{k+1} / r_k² is bounded (quadratic), with r in units
    // of the load, until the round-off floor (~1e-11 of the load: forces of 1e7 N from
    // stiffnesses of 1e11 N/m); a linear rate would make this ratio grow without bound.
    // Measured (slip): 2.5e8, 2.3e6, 5.6e4, 6.0e2, 7.1e-2, 4.4e-5 N: ratio 1.2 at 6.0e2 → 7.1e-2.
    const double scale = p.cwiseAbs().maxCoeff();
    int checked = 0;
    for (std::size_t i = 0; i + 1 < residuals.size(); ++i) {
      if (residuals[i] > 1e-3 * scale || residuals[i + 1] < 1e-11 * scale) continue;
      const double ratio = (residuals[i + 1] / scale) / std::pow(residuals[i] / scale, 2);
      EXPECT_LT(ratio, 1e3) << "iteration " << i << " push_y " << push_y;
      ++checked;
    }
    EXPECT_GE(checked, 1) << "push_y " << push_y;
  }
}

using test::still;

// Through run_analysis at its default adaptive stepping (each element with its own step limit
// and events): the face-on slab and the 2D Kelvin–Voigt contact within 0.5 % on every peak.
TEST(PolygonContactFaceOn, RunAnalysisAtDefaultsAgreesWithContact1D) {
  const double gap = 0.05, v0 = 1.0;
  const double kx = kSlabMass * std::pow(2 * std::numbers::pi / 2.0, 2);
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.keep_tension = true;
  Model m3 = slab_model(true, kx, kx, kx * polar_moment(1.0));
  m3.elements.push_back(
      std::make_unique<PolygonContact>("c", slab(0), wall_at(0.5 * kSide + gap), cfg));
  Model m1;
  m1.dofs = {{"slab/x", 0, 0}};
  m1.mass = Eigen::MatrixXd::Constant(1, 1, kSlabMass);
  m1.stiffness = Eigen::MatrixXd::Constant(1, 1, kx);
  m1.damping = Eigen::MatrixXd::Zero(1, 1);
  m1.influence = Eigen::VectorXd::Ones(1);
  const ImpactLawConfig law = face_on_kelvin_voigt(cfg);
  m1.elements.push_back(std::make_unique<Contact1D>("c", ContactBody{0, 1.0}, ContactBody{}, gap,
                                                    make_impact_law(law),
                                                    effective_mass(kSlabMass, kWallMass), 100));
  RunOptions o;
  o.initial_velocity = Eigen::Vector3d(v0, 0, 0);
  const AnalysisResult r3 = run_analysis(m3, still(0.3, 1e-3), o);
  o.initial_velocity = Eigen::VectorXd::Constant(1, v0);
  const AnalysisResult r1 = run_analysis(m1, still(0.3, 1e-3), o);
  const auto near = [](double a, double b, const char* what) {
    EXPECT_NEAR(a, b, 0.005 * std::abs(b)) << what;
  };
  near(r3.element_outputs[0][0].value, r1.element_outputs[0][0].value, "peak F_N");
  near(r3.element_outputs[0][3].value, r1.element_outputs[0][1].value, "peak penetration");
  near(r3.element_outputs[0][5].value, r1.element_outputs[0][3].value, "impact velocity");
  near(r3.displacement[0].value, r1.displacement[0].value, "peak displacement");
  near(r3.velocity[0].value, r1.velocity[0].value, "peak velocity");
  near(r3.absolute_acceleration[0].value, r1.absolute_acceleration[0].value, "peak acceleration");
  EXPECT_EQ(r3.element_outputs[0][4].value, 1.0);  // one impact
  EXPECT_LT(r3.displacement[2].value * 0.5 * kSide, 1e-6 * r3.displacement[0].value);
}

// An isolated slab (springs and a dashpot on its 3 DOFs) turned 0.2 rad, thrown obliquely at a
// wall with friction, through run_analysis: the energy balance closes and the contact only
// dissipates.
TEST(PolygonContactPassivity, RunAnalysisEnergyBalanceWithFriction) {
  const double kx = kSlabMass * std::pow(2 * std::numbers::pi / 2.0, 2);
  Model m = slab_model(true, kx, kx, kx * polar_moment(1.0));
  m.damping = 2 * 0.1 * (2 * std::numbers::pi / 2.0) * m.mass;
  const double theta0 = 0.2;
  const double reach = 0.5 * kSide * (std::cos(theta0) + std::sin(theta0));
  m.elements.push_back(std::make_unique<PolygonContact>("c", slab(0), wall_at(reach + 0.02),
                                                        PolygonContactConfig{}));
  RunOptions o;
  o.initial_displacement = Eigen::Vector3d(0, 0, theta0);
  o.initial_velocity = Eigen::Vector3d(1.2, 0.8, 0.0);
  const AnalysisResult r = run_analysis(m, still(1.0, 1e-3), o);
  const auto* c = static_cast<const PolygonContact*>(m.elements[0].get());
  EXPECT_GE(c->impacts(), 1);
  EXPECT_GT(r.element_outputs[0][1].value, 0.0);  // a tangential force acted
  EXPECT_GT(c->friction_dissipated(), 0.0);
  EXPECT_GE(r.element_outputs[0][10].value, 0.0);  // impact-dissipated
  EXPECT_GT(r.energy.hysteretic, 0.0);
  // Trapezoidal energy integration at the default tolerance (THEORY-notes: 4e-4 with 2D walls).
  EXPECT_LT(r.energy.relative_error, 5e-3);
}

// Options along the normal at one face-on state (A_c = L δ, δ_N = δ, w = L): the area law and
// a 2D law given k = k_N L agree; the exact overlap path gives the fast path's force; Hertz
// takes δ_N as its penetration.
TEST(PolygonContactOptions, NormalLawExactPathAndIndentationRule) {
  const double delta = 2e-3, rate = 0.3;
  const Eigen::VectorXd u = Eigen::Vector3d(0.01 + delta, 0, 0), v = Eigen::Vector3d(rate, 0, 0);
  const auto force = [&](const PolygonContactConfig& cfg) {
    PolygonContact c("c", slab(0), wall_at(5.01), cfg);
    c.begin_step(1e-4, false);
    c.set_trial(u, v);  // an onset inside this step (no event located): the law gets v_imp
    return c.output(0);
  };
  PolygonContactConfig area;
  area.friction = false;
  const double f_area = force(area);
  const double xi = kelvin_voigt_xi(area.restitution);
  const double m_eff = effective_mass(kSlabMass, kWallMass);
  EXPECT_NEAR(
      f_area,
      area.k_normal * kSide * delta + 2 * xi * std::sqrt(area.k_normal * kSide * m_eff) * rate,
      1e-9 * f_area);

  ImpactLawConfig law = face_on_kelvin_voigt(area);
  PolygonContactConfig kv = area;
  kv.normal_law = make_impact_law(law);
  EXPECT_NEAR(force(kv), f_area, 1e-9 * f_area);

  law.law = "hertz";
  law.k_h = 2.5e9;
  law.n = 1.5;
  PolygonContactConfig hertz = area;
  hertz.normal_law = make_impact_law(law);
  EXPECT_NEAR(force(hertz), 2.5e9 * std::pow(delta, 1.5), 1e-9 * 2.5e9 * std::pow(delta, 1.5));

  PolygonContactConfig exact = area;
  exact.overlap = OverlapMethod::kExact;
  EXPECT_NEAR(force(exact), f_area, 1e-12 * f_area);

  PolygonContactConfig mean = area;
  mean.indentation = IndentationRule::kMeanDepth;
  EXPECT_NEAR(force(mean), f_area, 1e-12 * f_area);  // a rectangle: the two rules agree
}

// Through the triangle → quadrilateral transition of a turned slab against the wall, moving at
// a fixed approach rate: with the thesis δ_N rule c_N jumps by √2 (A_c/δ_N goes from w/2 to w),
// with the mean-depth rule F_N is continuous.
TEST(PolygonContactOptions, DampingJumpOfTheThesisIndentationRule) {
  for (const IndentationRule rule : {IndentationRule::kThesis, IndentationRule::kMeanDepth}) {
    PolygonContactConfig cfg;
    cfg.friction = false;
    cfg.indentation = rule;
    PolygonContact c("c", slab(0), wall_at(6.0), cfg);
    c.begin_step(1e-3, false);
    Eigen::VectorXd u = Eigen::Vector3d(0, 0, 0.17), v = Eigen::Vector3d(0.5, 0, 0);
    const double du = 1e-4;
    double prev_damping = -1.0, jump = 1.0;
    int prev_count = 0;
    for (int i = 0; i < 25000; ++i) {
      u[0] = i * du;
      c.set_trial(u, v);
      if (c.output(11) == 0.0) continue;
      const double damping = c.output(0) - cfg.k_normal * c.output(2);  // c_N δ̇_N
      const int count =
          overlap_of(slab(0).shape.placed({u[0], 0, u[2]}), wall_at(6.0).shape).vertex_count;
      if (prev_count == 3 && count == 4) {
        jump = damping / prev_damping;
        break;
      }
      prev_count = count;
      prev_damping = damping;
    }
    if (rule == IndentationRule::kThesis)
      EXPECT_NEAR(jump, std::sqrt(2.0), 1e-3);
    else
      EXPECT_NEAR(jump, 1.0, 1e-3);
  }
}

// The analysis's last resort at its smallest step (Element::hold_branch): a held contact keeps its
// committed shape's δ_N rule. Committed as a triangle, a trial that is a quadrilateral has the
// triangle's c_N (1/√2 of its own) while held, its own again when released; committing a held
// trial keeps the triangle; a contact not closed at the commit has nothing to hold.
TEST(PolygonContactOptions, HeldBranchKeepsTheCommittedShapesIndentationRule) {
  PolygonContactConfig cfg;
  cfg.friction = false;
  PolygonContact c("c", slab(0), wall_at(6.0), cfg);
  c.begin_step(1e-3, false);
  Eigen::VectorXd u = Eigen::Vector3d(0, 0, 0.17), v = Eigen::Vector3d(0.5, 0, 0);
  const auto count_at = [&](double x) {
    return overlap_of(slab(0).shape.placed({x, 0, u[2]}), wall_at(6.0).shape).vertex_count;
  };
  // The last triangle and the first quadrilateral along the approach.
  double x_tri = -1.0, x_quad = -1.0;
  for (int i = 0; i < 25000 && x_quad < 0; ++i) {
    const int n = count_at(i * 1e-4);
    if (n == 3) x_tri = i * 1e-4;
    if (n == 4 && x_tri >= 0) x_quad = i * 1e-4;
  }
  ASSERT_GE(x_quad, 0.0);
  const auto damping = [&](double x) {  // c_N δ̇_N of the trial at x
    u[0] = x;
    c.set_trial(u, v);
    return c.output(0) - cfg.k_normal * c.output(2);
  };
  const double own = damping(x_quad);
  u[0] = x_tri;
  c.set_trial(u, v);
  c.commit();
  c.hold_branch(true);
  EXPECT_NEAR(damping(x_quad) / own, 1.0 / std::sqrt(2.0), 1e-12);
  c.commit();  // a held quadrilateral committed: still the triangle's rule while held
  EXPECT_NEAR(damping(x_quad) / own, 1.0 / std::sqrt(2.0), 1e-12);
  c.hold_branch(false);
  EXPECT_EQ(damping(x_quad), own);
  // Open at the commit: the first trial in contact takes its own shape, held or not.
  PolygonContact open("open", slab(0), wall_at(6.0), cfg);
  open.begin_step(1e-3, false);
  open.hold_branch(true);
  u[0] = x_quad;
  open.set_trial(u, v);
  EXPECT_EQ(open.output(0), c.output(0));
}

// Stick/slip transitions converge with the step: the slide of the pressed slab (its stop time
// and the friction-dissipated energy) at h = 4e-4, 2e-4, 1e-4 s.
TEST(PolygonContactFriction, SlideConvergesAsTheStepShrinks) {
  const double gap = 0.01, a_press = 2.0, v0 = 0.5;
  std::vector<double> stop, dissipated;
  for (const double h : {4e-4, 2e-4, 1e-4}) {
    PolygonContactConfig cfg;
    Model m = slab_model(false);
    m.elements.push_back(std::make_unique<PolygonContact>("c", slab(0, {0, 0}, false),
                                                          wall_at(0.5 * kSide + gap), cfg));
    const auto* c = static_cast<const PolygonContact*>(m.elements[0].get());
    const double delta_eq = kSlabMass * a_press / (cfg.k_normal * kSide);
    double t_stop = -1.0, v_prev = v0, t_prev = 0.0;
    run_fixed(m, h, 0.6, -a_press, Eigen::Vector2d(gap + delta_eq, 0.0), Eigen::Vector2d(0.0, v0),
              [&](const NewmarkStepper& s, double, double t) {
                // Stop time by linear interpolation of v_y through 0.
                if (t_stop < 0 && s.v()[1] <= 0.0)
                  t_stop = t_prev + (t - t_prev) * v_prev / (v_prev - s.v()[1]);
                v_prev = s.v()[1];
                t_prev = t;
              });
    stop.push_back(t_stop);
    dissipated.push_back(c->friction_dissipated());
  }
  // The stick → slip onset is located, so the slide hardly depends on the step: stop times
  // within 5e-5 and dissipated energies (spring–slider and tangential dashpot) within 1e-4 of
  // 42 kJ over a 4× range of steps. (|F_T| ≤ μ_s F_N from the first step: the trial force with
  // its dashpot decides the slip.)
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(stop[k], stop[2], 5e-5 * stop[2]) << "h index " << k;
    EXPECT_NEAR(dissipated[k], dissipated[2], 1e-4 * dissipated[2]) << "h index " << k;
  }
  EXPECT_NEAR(stop[2], v0 / (0.6 * a_press), 0.01 * stop[2]);
}

TEST(PolygonContactOutputs, NamesUnitsAndSnapshot) {
  PolygonContact c("pair", slab(0), wall_at(5.0), PolygonContactConfig{});
  ASSERT_EQ(c.output_count(), 12);
  EXPECT_EQ(c.output_name(0), "normal_force");
  EXPECT_EQ(c.output_unit(0), "N");
  EXPECT_EQ(c.output_name(9), "friction_dissipated_energy");
  EXPECT_EQ(c.output_unit(9), "J");
  EXPECT_EQ(c.output_unit(2), "m2");
  c.begin_step(1e-3, false);
  c.set_trial(Eigen::Vector3d(0.002, 0, 0), Eigen::Vector3d::Zero());
  const ContactSnapshot s = c.snapshot();
  EXPECT_TRUE(s.in_contact);
  EXPECT_NEAR(s.area, 0.02, 1e-12);
  EXPECT_NEAR(s.p_WC.x, 5.001, 1e-12);
  EXPECT_NEAR(s.n_AB.x, 1.0, 1e-15);
  EXPECT_NEAR(s.normal_force, 2.58e10 * 0.02, 1e-3);
}

// Which body is A does not matter: swapping A and B reverses n_AB and t_AB, and the forces on the
// DOFs are the same (slab–wall and slab–slab, with friction, at a trial after a committed step).
TEST(PolygonContactOutputs, SwappingTheBodiesGivesTheSameForces) {
  PolygonContactConfig cfg;
  for (const bool wall : {true, false}) {
    const PolygonBody a = slab(0), b = wall ? wall_at(5.0) : slab(3, {10.01, 3.0});
    PolygonContact ab("ab", a, b, cfg), ba("ba", b, a, cfg);
    const int n = wall ? 3 : 6;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
    u.head(3) << 0.012, 0.001, 0.004;
    v.head(3) << 0.4, 0.2, 0.03;
    if (!wall) u.tail(3) << -0.003, 0.0, -0.002;
    for (PolygonContact* c : {&ab, &ba}) {
      c->begin_step(1e-3, false);
      c->set_trial(u, v);
      c->commit();
      u[1] += 2e-3;  // slide on
      c->set_trial(u, v);
      u[1] -= 2e-3;
    }
    Eigen::VectorXd f_ab = Eigen::VectorXd::Zero(n), f_ba = Eigen::VectorXd::Zero(n);
    ab.add_force(f_ab);
    ba.add_force(f_ba);
    ASSERT_GT(ab.output(0), 0.0);
    EXPECT_LT((f_ab - f_ba).cwiseAbs().maxCoeff(), 1e-9 * f_ab.cwiseAbs().maxCoeff());
    EXPECT_NEAR(ab.snapshot().n_AB.x, -ba.snapshot().n_AB.x, 1e-12);
    EXPECT_NEAR(ab.output(1), ba.output(1), 1e-9 * std::abs(ab.output(0)));  // F_T
  }
}

}  // namespace
}  // namespace isopound

namespace isopound {
namespace {

// What counts as an impact (THEORY-notes "What counts as an impact"): a slab that overlaps a
// wall, is pulled back so hard that F_N is clamped at 0 (still overlapping), and then approaches
// again starts a second compressive force pulse: a second impact with force_pulses (the
// default), none with onsets. Loading again while still receding (δ̇_N < 1 mm/s) is no impact.
TEST(PolygonContactImpactCount, AClampedContactLoadingAgainWhileApproachingIsAnImpact) {
  for (const ImpactCount rule : {ImpactCount::kForcePulses, ImpactCount::kOnsets}) {
    PolygonContactConfig cfg;
    cfg.friction = false;
    cfg.impact_count = rule;
    PolygonContact c("slab|wall", slab(0), wall_at(0.5 * kSide + 1e-3), cfg);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
    const auto step = [&](double x, double rate) {
      u[0] = x;
      v[0] = rate;
      c.begin_step(1e-4, false);
      c.set_trial(u, v);
      c.commit();
    };
    step(2e-3, 0.5);  // 1 mm into the wall, approaching: the onset
    EXPECT_GT(c.snapshot().normal_force, 0.0);
    EXPECT_EQ(c.impacts_above_1mm_s(), 1);
    // Receding at 10 m/s: c_N δ̇_N (~ -6e8 N) outweighs k_N A_c (2.8e8 N): clamped at 0.
    step(2.1e-3, -10.0);
    EXPECT_TRUE(c.snapshot().in_contact);
    EXPECT_EQ(c.snapshot().normal_force, 0.0);
    step(2.1e-3, -1e-4);  // loads again while still receding: no impact
    EXPECT_GT(c.snapshot().normal_force, 0.0);
    EXPECT_EQ(c.impacts_above_1mm_s(), 1);
    step(2.1e-3, -10.0);  // clamped again
    EXPECT_EQ(c.snapshot().normal_force, 0.0);
    step(2.1e-3, 0.01);  // loads again approaching at 10 mm/s
    EXPECT_GT(c.snapshot().normal_force, 0.0);
    const int expected = rule == ImpactCount::kForcePulses ? 2 : 1;
    EXPECT_EQ(c.impacts_above_1mm_s(), expected);
    EXPECT_EQ(c.impacts(), expected);
  }
}

}  // namespace
}  // namespace isopound

namespace isopound {
namespace {

// The step policy is the 2D contact's (contact_step.h): face-on, the polygon contact asks for the
// same step as a Kelvin–Voigt Contact1D of k = k_N L at every state of an approach (time of
// impact, and its floor near the wall), at the onset (1/32 of the contact step) and through the
// graded steps after it. Differences come only from the witness rate's central difference and
// the contact period's Newton iteration (< 1e-6 relative).
TEST(PolygonContactStepLimit, FaceOnEqualsTheKelvinVoigtContact1D) {
  const double gap = 1e-3, h = 2e-5;
  PolygonContactConfig cfg;
  cfg.friction = false;
  cfg.keep_tension = true;
  PolygonContact polygon("slab|wall", slab(0), wall_at(0.5 * kSide + gap), cfg);
  const ImpactLawConfig law = face_on_kelvin_voigt(cfg);
  const double m_eff = effective_mass(kSlabMass, kWallMass);
  Contact1D line("slab|wall", {0, 1.0}, {-1, 0.0}, gap, make_impact_law(law), m_eff,
                 cfg.steps_per_contact);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
  double x = -0.005, rate = 0.3;
  int compared = 0, in_contact = 0;
  for (int n = 0; n < 20000 && x < gap + 2e-4; ++n) {
    // Decelerating approach (1 m/s² towards the wall is not enough to stop it).
    x += h * rate;
    rate -= h * 1.0;
    u[0] = x;
    v[0] = rate;
    for (Element* e : {static_cast<Element*>(&polygon), static_cast<Element*>(&line)}) {
      e->begin_step(h, false);
      e->set_trial(u, v);
      e->commit();
    }
    const double a = polygon.step_limit(), b = line.step_limit();
    if (b < 1.0) {  // a limit that can bind
      EXPECT_NEAR(a, b, 1e-6 * b) << "step " << n << ", x = " << x;
      ++compared;
      in_contact += x > gap;
    }
  }
  EXPECT_GT(compared, 100);
  EXPECT_GE(in_contact, 6);  // the onset and the graded steps after it
}

}  // namespace
}  // namespace isopound

namespace isopound {
namespace {

// Coulomb holds from the first instant of a contact: a slab that reaches a wall while sliding
// along it at 2 m/s (c_T u̇_T ~ 18 MN > μ_s F_N) starts slipping at the onset (|F_T| = μ_k F_N),
// not with the dashpot acting unbounded at the located onset (it was 2.3x F_N between adjacent
// floors).
TEST(PolygonContactFriction, ASlabArrivingWhileSlidingSlipsFromTheOnset) {
  const double gap = 1e-5, h = 4e-4;
  PolygonContactConfig cfg;
  PolygonContact c("slab|wall", slab(0), wall_at(0.5 * kSide + gap), cfg);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3), v = Eigen::VectorXd::Zero(3);
  v[0] = 0.05;  // approaching the wall slowly: F_N = c_N v_imp ~ 3 MN
  v[1] = 2.0;   // sliding along it
  const auto trial = [&](double t, double step, bool freeze) {
    u[0] = v[0] * t;
    u[1] = v[1] * t;
    c.begin_step(step, freeze);
    c.set_trial(u, v);
  };
  trial(0.0, h, false);
  c.commit();
  trial(h, h, false);  // the gap closes at t = gap / 0.05 = 2e-4 s, half-way
  const double theta = c.event_fraction();
  ASSERT_NEAR(theta, 0.5, 1e-6);
  c.revert();
  trial(theta * h, theta * h, true);  // the step cut to end at the onset
  c.commit();
  ASSERT_TRUE(c.settle_event());
  trial(theta * h, theta * h, true);  // the restart's evaluation at the onset
  const ContactSnapshot s = c.snapshot();
  ASSERT_TRUE(s.in_contact);
  EXPECT_GT(s.normal_force, 0.0);  // the Kelvin–Voigt jump c_N v_imp
  EXPECT_TRUE(s.slipping);
  EXPECT_NEAR(std::abs(s.tangential_force), cfg.mu_kinetic * s.normal_force, 1e-9 * s.normal_force);
}

}  // namespace
}  // namespace isopound
