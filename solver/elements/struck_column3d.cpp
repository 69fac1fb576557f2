// A slab against one column of a 3D storey: the massless node (x, y) found by a damped Newton
// iteration on its two equilibrium equations (column + contact; in contact with the slope of
// differences of the residual, and one-sided slopes at kinks), then condensed out of the tangent
// on the slab and the two floors.
#include "solver/elements/struck_column3d.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "solver/elements/plan_pair.h"

namespace isopound {

namespace {

constexpr int kRest[9] = {0, 1, 2, 5, 6, 7, 8, 9, 10};  // z without the node

ConvexPolygon polygon_of(const std::vector<Vec2>& v) {
  return ConvexPolygon(std::span<const Vec2>(v.data(), v.size()));
}

PolygonBody slab_body(const StruckColumn3DSpec& s) {
  return PolygonBody{0, 1, 2, {0.0, 0.0}, polygon_of(s.slab_plan_W), s.slab_mass};
}

PolygonBody section_body(const StruckColumn3DSpec& s) {
  return PolygonBody{3, 4, 11, s.p_W, polygon_of(s.section_W), s.struck_mass};
}

// The slab-to-slab law with the mean-depth indentation in its damping, c_N ∝ √(A_c/δ_N) = √w:
// the thesis rule's δ_N = 2A_c/w for a triangle halves c_N's A_c/δ_N when the overlap turns
// from a triangle into a quadrilateral, a force jump that a massless node cannot balance. For
// the same reason the force is continuous otherwise too (PolygonContactConfig::continuous_force:
// no mu_s -> mu_k drop inside a trial, no sign flip of a slip frozen where the node would stick,
// no jump of the shallow overlap's shape at the sliver's depth).
PolygonContactConfig struck_law(PolygonContactConfig law) {
  law.indentation = IndentationRule::kMeanDepth;
  law.continuous_force = true;
  return law;
}

// The slab-to-section contact: a non-convex slab's overlap with the section through a PlanPair of
// one slot (a section is small beside a slab: its overlap is one part).
PolygonContact make_contact(const std::string& label, const StruckColumn3DSpec& s,
                            const PolygonContactConfig& law) {
  if (s.slab_outline_W.empty())
    return PolygonContact(label, slab_body(s), section_body(s), struck_law(law));
  auto pair = std::make_shared<PlanPair>(
      PlanPairBody{SimplePolygon(std::span<const Vec2>(s.slab_outline_W)), {0.0, 0.0}, true},
      PlanPairBody{SimplePolygon(std::span<const Vec2>(s.section_W)), s.p_W, true}, 1, law.overlap);
  return PolygonContact(label, slab_body(s), section_body(s), struck_law(law), std::move(pair), 0);
}

}  // namespace

StruckColumn3D::StruckColumn3D(std::string label, const StruckColumn3DSpec& spec,
                               const PolygonContactConfig& law)
    : label_(std::move(label)),
      spec_(spec),
      column_{HingedColumn(spec.axis[0]), HingedColumn(spec.axis[1])},
      twist_weight_(spec.axis[0].node / spec.axis[0].length),
      contact_(make_contact(label_, spec, law)),
      zl_(Eigen::VectorXd::Zero(kLocal)),
      zdl_(Eigen::VectorXd::Zero(kLocal)),
      fl_(Eigen::VectorXd::Zero(kLocal)),
      z_commit_(Eigen::VectorXd::Zero(kLocal)),
      zd_commit_(Eigen::VectorXd::Zero(kLocal)),
      kk_(Eigen::MatrixXd::Zero(kLocal, kLocal)),
      kd_(Eigen::MatrixXd::Zero(kLocal, kLocal)) {
  if (spec.slab[0] < 0 || spec.upper[0] < 0)
    throw std::invalid_argument(label_ + ": a struck column needs a slab and a floor above");
  // Axis i of the section: a1 = (c, s), a2 = (-s, c). A floor point at p moves by
  // (u - p.y theta, v + p.x theta); its component along a is a.x u + a.y v + (p x a) theta.
  const double c = std::cos(spec.orientation), s = std::sin(spec.orientation);
  const Vec2 a[2] = {{c, s}, {-s, c}};
  const Vec2 p = spec.p_W;
  for (int i = 0; i < 2; ++i) {
    Map3xL& m = map_[i];
    m.setZero();
    const double r[3] = {a[i].x, a[i].y, p.x * a[i].y - p.y * a[i].x};
    for (int k = 0; k < 3; ++k) {
      m(0, 5 + k) = r[k];
      m(2, 8 + k) = r[k];
    }
    m(1, 3) = a[i].x;
    m(1, 4) = a[i].y;
  }
  for (int i = 0; i < 2; ++i) {
    state_[i] = column_[i].respond(Eigen::Vector3d::Zero(), plastic_commit_[i]);
    // The fixed-fixed beam's elastic stiffness at the node, 3 E I L^3 / (a^3 b^3), times 1 m.
    const HingedColumnSection& c = spec.axis[i];
    const double b = c.length - c.node;
    force_per_length_ = std::max(force_per_length_, 3 * c.E * c.I * std::pow(c.length, 3) /
                                                        (std::pow(c.node, 3) * std::pow(b, 3)));
  }
}

bool StruckColumn3D::add_dofs(std::vector<int>& dofs) const {
  for (const std::array<int, 3>* d : {&spec_.slab, &spec_.lower, &spec_.upper})
    for (const int k : *d)
      if (k >= 0) dofs.push_back(k);
  return true;
}

int StruckColumn3D::global_dof(int local) const {
  if (local < 3) return spec_.slab[local];
  if (local < 5) return -1;
  if (local < 8) return spec_.lower[local - 5];
  return spec_.upper[local - 8];
}

void StruckColumn3D::begin_step(double h, bool freeze_status) {
  h_ = h;
  contact_.begin_step(h, freeze_status);
}

void StruckColumn3D::gather(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  for (const int k : kRest) {
    const int g = global_dof(k);
    zl_(k) = g >= 0 ? u[g] : 0.0;
    zdl_(k) = g >= 0 ? v[g] : 0.0;
  }
  set_twist();
}

void StruckColumn3D::set_twist() {
  const double w = twist_weight_;
  zl_(kTwist) = (1.0 - w) * zl_(7) + w * zl_(10);
  zdl_(kTwist) = (1.0 - w) * zdl_(7) + w * zdl_(10);
}

void StruckColumn3D::spread_twist_force() {
  fl_(7) += (1.0 - twist_weight_) * fl_(kTwist);
  fl_(10) += twist_weight_ * fl_(kTwist);
  fl_(kTwist) = 0.0;
}

Eigen::Vector2d StruckColumn3D::chord(const Eigen::VectorXd& z, double w) const {
  const Vec2 p = spec_.p_W;
  const auto at = [&](int o) {
    return Eigen::Vector2d(z(o) - p.y * z(o + 2), z(o + 1) + p.x * z(o + 2));
  };
  return (1.0 - w) * at(5) + w * at(8);
}

Eigen::Vector2d StruckColumn3D::node_residual(Eigen::Matrix2d* slope) {
  Eigen::Matrix2d k_nn = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 2, 9> k_nr = Eigen::Matrix<double, 2, 9>::Zero();
  fl_.setZero();
  for (int i = 0; i < 2; ++i) {
    const Eigen::Matrix<double, 3, 1> q = map_[i] * zl_;
    state_[i] = column_[i].respond(q, plastic_commit_[i]);
    fl_.noalias() += map_[i].transpose() * state_[i].force;
    // The node's rows of M^T T M (M: map_[i]), the only ones needed.
    const Eigen::Matrix<double, 2, 3> a = map_[i].middleCols<2>(3).transpose() * state_[i].tangent;
    k_nn.noalias() += a * map_[i].middleCols<2>(3);
    for (int j = 0; j < 9; ++j) k_nr.col(j).noalias() += a * map_[i].col(kRest[j]);
  }
  // The node's rate: behind the contact's dashpot the backward difference (L-stable: the
  // trapezoidal rule would leave a massless node ringing); free of it, the quasi-static rate
  // through the column, exact as the floors' rates.
  const bool damped = damped_commit_;
  Eigen::Vector2d rate;
  if (damped)
    rate = h_ > 0 ? Eigen::Vector2d((zl_.segment<2>(3) - node_commit_) / h_) : rate_commit_;
  else {
    Eigen::Matrix<double, 9, 1> vr;
    for (int j = 0; j < 9; ++j) vr(j) = zdl_(kRest[j]);
    rate = -k_nn.partialPivLu().solve(k_nr * vr);
  }
  zdl_.segment<2>(3) = rate;
  contact_.set_trial(zl_, zdl_);
  // In contact, the node's rate along the normal is set so that the approach rate is the
  // backward difference of the penetration depth D (-separation, continuous in the placement)
  // from max(D_commit, 0): (D - D_c+) / h, at a restart 0 after an onset, else the committed
  // one. The dashpot force then starts from zero at touch (the massless node takes the slab's
  // approach at once) and is continuous in the node's position, so the node always has a
  // balanced position. (With the node's own rate, c_N v_impact jumped on at A_c -> 0+ and the
  // node could stop out of balance at the contact surface.)
  depth_rule_ = contact_.trial_closed() && (h_ > 0 || !damped);
  if (depth_rule_) {
    const Vec2 n = contact_.snapshot().n_AB;
    normal_ = Eigen::Vector2d(n.x, n.y);
    const double target = h_ > 0 ? (contact_.trial_depth() - depth_commit_) / h_ : 0.0;
    zdl_.segment<2>(3) += (contact_.trial_approach_rate() - target) * normal_;
    contact_.set_trial(zl_, zdl_);
  }
  contact_.add_force(fl_);
  spread_twist_force();
  if (slope) *slope = k_nn;  // the column's; a closed contact's by differences (set_trial)
  return fl_.segment<2>(3);
}

void StruckColumn3D::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  gather(u, v);
  solve_node();
}

void StruckColumn3D::solve_node() {
  // The node's residual and its slope at n. In contact the slope is the central difference of
  // the residual itself (the contact's law, the depth rule and the friction return map as
  // applied; the node's rate makes it stiff, c / h): a step of 1e-11 m resolves the friction's
  // stick ramp (width ~ mu F_N h / c_T) at any step and stays well above the round-off of the
  // placements (~1e-15 m). The one-sided differences are kept for kinks (below).
  // The slope is taken only where a Newton step starts from (not at trial points of the line
  // search, nor where the node is balanced): its differences cost four residuals.
  std::array<Eigen::Matrix2d, 2> one_sided;  // forward, backward
  Eigen::Matrix2d column_slope;              // the column's, at the last residual's node
  const auto residual = [&](const Eigen::Vector2d& n) {
    zl_.segment<2>(3) = n;
    return node_residual(&column_slope);
  };
  // The slope at n, the node of the last residual; returns the residual there, re-evaluated.
  const auto slope_at = [&](const Eigen::Vector2d& n, Eigen::Matrix2d& slope) {
    slope = column_slope;
    one_sided = {slope, slope};
    Eigen::Vector2d g = fl_.segment<2>(3);
    if (!contact_.trial_closed()) return g;
    constexpr double eps = 1e-11;
    Eigen::Vector2d g_plus[2], g_minus[2];
    for (int j = 0; j < 2; ++j) {
      zl_.segment<2>(3) = n + eps * Eigen::Vector2d::Unit(j);
      g_plus[j] = node_residual(nullptr);
      zl_.segment<2>(3) = n - eps * Eigen::Vector2d::Unit(j);
      g_minus[j] = node_residual(nullptr);
    }
    zl_.segment<2>(3) = n;
    g = node_residual(nullptr);
    for (int j = 0; j < 2; ++j) {
      slope.col(j) = (g_plus[j] - g_minus[j]) / (2 * eps);
      one_sided[0].col(j) = (g_plus[j] - g) / eps;
      one_sided[1].col(j) = (g - g_minus[j]) / eps;
    }
    return g;
  };
  // Predictor: the node moves with the elastic shape of the column between its floors (exact
  // for an elastic column away from the slab). A restart (zero-length step, the floors where
  // they were) starts from the committed node: there it is balanced unless the settled event
  // changed the contact's force (an onset inside the overlap, a stick-slip switch).
  Eigen::Vector2d n = h_ > 0
                          ? Eigen::Vector2d(offset_commit_ + chord(zl_, column_[0].shape_at_node()))
                          : node_commit_;
  // Converged: the residual at the round-off of the column's forces, or of its force at a node
  // moved by the round-off of its placement (an unloaded one).
  const auto converged = [&](const Eigen::Vector2d& g) {
    return g.norm() <= 1e-13 * (column_force() + 1e-2 * force_per_length_);
  };
  // Newton from the node; true when converged.
  const auto solve = [&](Eigen::Vector2d& node, Eigen::Vector2d& g, Eigen::Matrix2d& slope) {
    g = residual(node);
    bool have_slope = false;
    for (int it = 0; it < 100; ++it) {
      if (converged(g)) return true;
      if (!have_slope) g = slope_at(node, slope), have_slope = true;
      // Newton with backtracking (the residual's norm must fall). At a kink (the no-tension
      // clamp, stick to slip, a hinge) the central slope averages the two sides and its step may
      // not descend: then the slopes of each side, one-sided per coordinate.
      // (Balanced to 1e-6 of the column's forces, the round-off of the dashpot's D / h at the
      // shortest steps is near: the kink slopes are not tried.)
      const std::array<Eigen::Matrix2d, 2> side = one_sided;
      const int candidates = g.norm() <= 1e-6 * column_force() ? 1 : 5;
      bool moved = false;
      for (int candidate = 0; candidate < candidates && !moved; ++candidate) {
        Eigen::Matrix2d j_try = slope;
        if (candidate > 0)
          for (int c = 0; c < 2; ++c) j_try.col(c) = side[((candidate - 1) >> c) & 1].col(c);
        const Eigen::Vector2d step = -j_try.partialPivLu().solve(g);
        if (!step.allFinite() || step.norm() <= 1e-14 * (1e-3 + node.norm())) continue;
        double t = 1.0;
        for (int cut = 0; cut < 30; ++cut, t *= 0.5) {
          const Eigen::Vector2d g_next = residual(node + t * step);
          if (g_next.norm() < g.norm()) {
            node += t * step;
            g = g_next;
            have_slope = false;
            moved = true;
            break;
          }
        }
      }
      if (!moved) {
        g = residual(node);  // the state back at the best node
        return false;
      }
    }
    return false;
  };
  Eigen::Matrix2d slope;
  Eigen::Vector2d g;
  if (!solve(n, g, slope) && contact_.trial_closed() && g.norm() > 1e-6 * column_force()) {
    // The return map's stick band is narrow at short steps (2 mu F_N / (k_T + c_T / h) wide in
    // the node's position) and the residual flat in slip outside it: Newton from a slip may not
    // find a node that sticks. The two smooth branches apart, stick then slip, from the best
    // node; the node is taken where the law itself (the status then consistent) balances best.
    for (const auto status :
         {PolygonContact::FrictionStatus::kStick, PolygonContact::FrictionStatus::kSlip}) {
      Eigen::Vector2d n_branch = n, g_branch;
      contact_.force_friction_status(status);
      solve(n_branch, g_branch, slope);
      contact_.force_friction_status(PolygonContact::FrictionStatus::kFree);
      g_branch = residual(n_branch);
      const bool better = g_branch.norm() < g.norm();
      if (better) n = n_branch, g = g_branch;
      if (converged(g)) break;
    }
    g = residual(n);
  }
}

void StruckColumn3D::add_force(Eigen::VectorXd& f) const {
  for (const int k : kRest) {
    const int d = global_dof(k);
    if (d >= 0) f[d] += fl_(k);
  }
}

void StruckColumn3D::condensed_tangent(double velocity_factor) const {
  // The contact's k and c apart: the slab's rate follows the stepper's factor, the node's its
  // own rule (1/h behind a dashpot, else none).
  kk_.setZero();
  contact_.add_tangent(kk_, 0.0);
  kd_.setZero();
  contact_.add_tangent(kd_, 1.0);
  kd_ -= kk_;
  for (int j = 0; j < kLocal; ++j)
    if (j != 3 && j != 4) kz_.col(j) = kk_.col(j) + kd_.col(j) * velocity_factor;
  kz_.middleCols<2>(3) = kk_.middleCols<2>(3);
  if (velocity_factor > 0 && h_ > 0 && (damped_commit_ || depth_rule_)) {
    const Eigen::Matrix<double, kLocal, 2> k_v = kd_.middleCols<2>(3);
    kz_.middleCols<2>(3).noalias() += k_v * node_rate_slope() / h_;
    // The depth rule's normal rate n.(v_slab) - (D - D_c+) / h from the slab's translation
    // (its rotation and the twist left out): its dashpot no longer sees the slab's rate.
    if (depth_rule_)
      kz_.leftCols<2>().noalias() +=
          k_v * normal_ * normal_.transpose() * (velocity_factor - 1.0 / h_);
  }
  for (int i = 0; i < 2; ++i) kz_ += map_[i].transpose() * state_[i].tangent * map_[i];
  // The twist is T z: K <- T^T K T folds its column, then its row, into the floors' theta.
  const double w = twist_weight_;
  kz_.col(7) += (1.0 - w) * kz_.col(kTwist);
  kz_.col(10) += w * kz_.col(kTwist);
  kz_.row(7) += (1.0 - w) * kz_.row(kTwist);
  kz_.row(10) += w * kz_.row(kTwist);
  const Eigen::Matrix2d k_nn = kz_.block<2, 2>(3, 3);
  const Eigen::PartialPivLU<Eigen::Matrix2d> lu(k_nn);
  const bool invertible = std::abs(k_nn.determinant()) > 0;
  for (int j = 0; j < 9; ++j) {
    Eigen::Vector2d k_nj = kz_.block<2, 1>(3, kRest[j]);
    const Eigen::Vector2d x =
        invertible ? Eigen::Vector2d(lu.solve(k_nj)) : Eigen::Vector2d::Zero();
    for (int i = 0; i < 9; ++i)
      kc_(i, j) = kz_(kRest[i], kRest[j]) - kz_.block<1, 2>(kRest[i], 3).dot(x);
  }
}

void StruckColumn3D::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  condensed_tangent(velocity_factor);
  for (int i = 0; i < 9; ++i) {
    const int di = global_dof(kRest[i]);
    if (di < 0) continue;
    for (int j = 0; j < 9; ++j) {
      const int dj = global_dof(kRest[j]);
      if (dj >= 0) K(di, dj) += kc_(i, j);
    }
  }
}

void StruckColumn3D::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  condensed_tangent(0.0);
  for (int i = 0; i < 9; ++i) {
    const int di = global_dof(kRest[i]);
    if (di < 0) continue;
    for (int j = 0; j < 9; ++j) {
      const int dj = global_dof(kRest[j]);
      if (dj >= 0) y[di] += kc_(i, j) * x[dj];
    }
  }
}

double StruckColumn3D::power(const Eigen::VectorXd& v) const {
  double p = 0.0;
  for (const int k : kRest) {
    const int d = global_dof(k);
    if (d >= 0) p += v[d] * fl_(k);
  }
  return p;
}

double StruckColumn3D::stored_energy() const {
  return state_[0].stored_energy + state_[1].stored_energy + contact_.stored_energy();
}

double StruckColumn3D::indicator_at(double theta, const Eigen::VectorXd& z1,
                                    const Eigen::VectorXd& zd1, double h) {
  for (const int k : kRest) {
    zl_(k) = z_commit_(k) + theta * (z1(k) - z_commit_(k));
    zdl_(k) = zd_commit_(k) + theta * (zd1(k) - zd_commit_(k));
  }
  set_twist();
  h_ = theta * h;
  contact_.begin_step(h_, false);
  solve_node();
  return contact_.event_indicator(false);
}

double StruckColumn3D::event_fraction() {
  const double theta = contact_.event_fraction();
  if (!(theta > 0 && theta < 1)) return theta;
  // Shorter than this (s), a step cut at an event is round-off: the event is settled at the
  // step's start or end (a cut ending that close to the end left the remainder as a step).
  constexpr double kShortestCut = 1e-9;
  constexpr double kSettledAtStart = 2e-4;
  const double h = h_;
  double located = theta;
  const double f0 = contact_.event_indicator(true), f1 = contact_.event_indicator(false);
  if (contact_.pending_has_indicator() && f0 > 0 && f1 < 0) {
    // Illinois (regula falsi halving a retained end's value) on the node solved along the step,
    // to 1e-3 of the fraction or 1 ns; the step is cut at the bracket's end past the event, so
    // that the next step begins on the event's far side (cut before it, the linear guess from
    // there fell short again). A stepper rejects the trial after a cut: the probes may leave it
    // anywhere, but the contact's pending event and the trial are restored.
    const Eigen::VectorXd z1 = zl_, zd1 = zdl_;
    double lo = 0.0, hi = 1.0, flo = f0, fhi = f1;
    int side = 0;
    for (int it = 0; it < 40 && (hi - lo) * h > kShortestCut && hi - lo > 1e-3 * hi; ++it) {
      const double t = std::clamp((lo * fhi - hi * flo) / (fhi - flo), lo + 1e-3 * (hi - lo),
                                  hi - 1e-3 * (hi - lo));
      const double f = indicator_at(t, z1, zd1, h);
      if (f > 0) {
        lo = t, flo = f;
        if (side == 1) fhi *= 0.5;
        side = 1;
      } else {
        hi = t, fhi = f;
        if (side == -1) flo *= 0.5;
        side = -1;
      }
    }
    zl_ = z1, zdl_ = zd1, h_ = h;
    contact_.begin_step(h, false);
    solve_node();
    contact_.event_fraction();
    located = hi;
  }
  // A kink of a continuous force (no-tension, phase) at the step's very start: a short step past
  // it rather than none (a stepper settles an event within 1e-4 of the start at once, element.h,
  // and a kink settled would be found again).
  if (contact_.pending_is_kink())
    located = std::min(1.0, std::max({located, 1.0001 * kShortestCut / h, kSettledAtStart}));
  if (located * h < kShortestCut) return 0.0;
  if ((1.0 - located) * h <= kShortestCut) return 1.0 - 1e-15;
  return located;
}

Eigen::Matrix2d StruckColumn3D::node_rate_slope() const {
  // Backward difference: I; the depth rule after an onset (quasi-static across the normal):
  // n n^T. (Behind the dashpot the depth rule's normal part is I too: D falls as the node moves
  // along n.)
  if (damped_commit_) return Eigen::Matrix2d::Identity();
  return depth_rule_ ? Eigen::Matrix2d(normal_ * normal_.transpose()) : Eigen::Matrix2d::Zero();
}

bool StruckColumn3D::contact_damped() const {
  kk_.setZero();
  contact_.add_tangent(kk_, 0.0);
  kd_.setZero();
  contact_.add_tangent(kd_, 1.0);
  return (kd_.block<2, 2>(3, 3) - kk_.block<2, 2>(3, 3)).cwiseAbs().maxCoeff() > 0;
}

void StruckColumn3D::commit() {
  // Element passivity (episodes()): the work of the DOFs' rates on the element's forces.
  double p = 0.0;
  for (const int k : kRest) p += zdl_(k) * fl_(k);
  work_ += 0.5 * (p + power_commit_) * h_;
  gross_work_ += 0.5 * (std::abs(p) + std::abs(power_commit_)) * h_;
  power_commit_ = p;
  const bool closed = contact_.trial_closed();
  const double dissipated = work_ - stored_energy();
  if (closed && !closed_commit_) {
    episode_dissipated_ = dissipated;
    episode_gross_ = gross_work_;
  } else if (!closed && closed_commit_) {
    episode_work_.end(-(dissipated - episode_dissipated_), gross_work_ - episode_gross_);
  }
  closed_commit_ = closed;
  contact_.commit();
  for (int i = 0; i < 2; ++i) {
    hinge_energy_ +=
        spec_.axis[i].yield_moment * (state_[i].plastic - plastic_commit_[i]).cwiseAbs().sum();
    plastic_commit_[i] = state_[i].plastic;
  }
  z_commit_ = zl_;
  zd_commit_ = zdl_;
  node_commit_ = zl_.segment<2>(3);
  rate_commit_ = zdl_.segment<2>(3);
  offset_commit_ = node_commit_ - chord(zl_, column_[0].shape_at_node());
  damped_commit_ = contact_damped();
  depth_commit_ = contact_.trial_closed() ? std::max(contact_.trial_depth(), 0.0) : 0.0;
  if (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity) shear_failed_ = true;
  shear_failed_commit_ = shear_failed_;
}

void StruckColumn3D::revert() {
  contact_.revert();
  zl_.segment<2>(3) = node_commit_;
  zdl_.segment<2>(3) = rate_commit_;
  shear_failed_ = shear_failed_commit_;
}

double StruckColumn3D::shear() const {
  const double lower = std::hypot(state_[0].shear_lower, state_[1].shear_lower);
  const double upper = std::hypot(state_[0].shear_upper, state_[1].shear_upper);
  return std::max(lower, upper);
}

Vec2 StruckColumn3D::local_drift() const {
  const HingedColumnSection& s = spec_.axis[0];
  const Eigen::Vector2d d = zl_.segment<2>(3) - chord(zl_, s.node / s.length);
  return {d.x(), d.y()};
}

double StruckColumn3D::hinge_dissipated_energy() const {
  double e = hinge_energy_;
  for (int i = 0; i < 2; ++i)
    e += spec_.axis[i].yield_moment * (state_[i].plastic - plastic_commit_[i]).cwiseAbs().sum();
  return e;
}

namespace {
constexpr const char* kNames[] = {
    "column_shear",           "shear_failed",     "moment_1_bottom", "moment_1_node",
    "moment_1_top",           "moment_2_bottom",  "moment_2_node",   "moment_2_top",
    "ductility_1_bottom",     "ductility_1_node", "ductility_1_top", "ductility_2_bottom",
    "ductility_2_node",       "ductility_2_top",  "local_drift_x",   "local_drift_y",
    "hinge_dissipated_energy"};
constexpr const char* kUnits[] = {"N", "-", "N m", "N m", "N m", "N m", "N m", "N m", "-",
                                  "-", "-", "-",   "-",   "-",   "m",   "m",   "J"};
}  // namespace

std::string StruckColumn3D::output_name(int i) const {
  const int c = contact_.output_count();
  return i < c ? contact_.output_name(i) : kNames[i - c];
}

Element::OutputKind StruckColumn3D::output_kind(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output_kind(i);
  return i == c + 1 ? OutputKind::kState : OutputKind::kContinuous;  // shear_failed
}

std::string StruckColumn3D::output_unit(int i) const {
  const int c = contact_.output_count();
  return i < c ? contact_.output_unit(i) : kUnits[i - c];
}

double StruckColumn3D::output(int i) const {
  const int c = contact_.output_count();
  if (i < c) return contact_.output(i);
  const int k = i - c;
  if (k == 0) return shear();
  if (k == 1) return shear_failed_ || (spec_.shear_capacity > 0 && shear() >= spec_.shear_capacity);
  if (k < 8) return state_[(k - 2) / 3].moment((k - 2) % 3);
  if (k < 14) {
    const HingedColumnSection& s = spec_.axis[(k - 8) / 3];
    const double theta_y = s.yield_moment * s.length / (6.0 * s.E * s.I);
    return theta_y > 0 ? 1.0 + std::abs(state_[(k - 8) / 3].plastic((k - 8) % 3)) / theta_y : 0.0;
  }
  if (k == 14) return local_drift().x;
  if (k == 15) return local_drift().y;
  return hinge_dissipated_energy();
}

}  // namespace isopound
