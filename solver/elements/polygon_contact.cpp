// 3D polygon contact element: overlap-area normal force with Kelvin–Voigt damping, tangential
// spring with a Coulomb return map, Hermite-witness events; tangent by forward-mode
// differentiation (polygon_contact_tangent.cpp) or, where that does not apply, central differences.
#include "solver/elements/polygon_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "solver/elements/contact_step.h"
#include "solver/elements/witness.h"

namespace isopound {

namespace {

constexpr double kInsideEventFraction = 1e-4;    // continuous-force events only strictly inside
constexpr double kCountedImpactVelocity = 1e-3;  // m/s: impacts_above_1mm_s() counts from here
// Depth of the sliver that gives a contact at A_c → 0 (and any shallower overlap) its shape
// (w, n, C), relative to the body size (0.17 µm for a 16.5 m slab). The limit is discontinuous
// at face-on: a slab turned by θ has its sliver's centroid θL²/(12 δ) off the middle, so a
// shallow sliver turns round-off rotations into torques (THEORY-notes, "Face-on rotation").
constexpr double kSurfaceSliver = 1e-8;

Vec2 rotate(Vec2 p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

double length(Vec2 a) {
  return std::hypot(a.x, a.y);
}

// Velocity of the material point of a body currently at p: (u̇, v̇) + θ̇ ẑ × (p − O').
Vec2 point_velocity(double ud, double vd, double thetad, Vec2 r_OP) {
  return {ud - thetad * r_OP.y, vd + thetad * r_OP.x};
}

double sign_or_zero(double x) {
  return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
}

}  // namespace

ContactStiffness contact_stiffness_from_materials(double e_static_1, double nu_1, double e_static_2,
                                                  double nu_2) {
  for (const double e : {e_static_1, e_static_2})
    if (!(e > 0) || !std::isfinite(e))
      throw std::invalid_argument("contact stiffness: E_st must be a positive modulus (Pa)");
  for (const double nu : {nu_1, nu_2})
    if (!(nu > -1.0 && nu < 0.5))
      throw std::invalid_argument("contact stiffness: Poisson's ratio must be in (-1, 0.5)");
  // eq. 5.23 is empirical in GPa: E_dyn[GPa] = 5.82 E_st[GPa]^0.63.
  const auto dynamic = [](double e_pa) { return 5.82 * std::pow(e_pa * 1e-9, 0.63) * 1e9; };
  const double e1 = dynamic(e_static_1), e2 = dynamic(e_static_2);
  const double g1 = e1 / (2 * (1 + nu_1)), g2 = e2 / (2 * (1 + nu_2));
  ContactStiffness k;
  k.k_normal = 1.0 / ((1 - nu_1 * nu_1) / e1 + (1 - nu_2 * nu_2) / e2);
  k.k_tangential = 1.0 / ((2 - nu_1) / g1 + (2 - nu_2) / g2);
  return k;
}

PolygonContact::PolygonContact(std::string label, PolygonBody a, PolygonBody b,
                               const PolygonContactConfig& cfg)
    : label_(std::move(label)), a_(std::move(a)), b_(std::move(b)), cfg_(cfg) {
  const auto require = [&](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("polygon contact '" + label_ + "': " + what);
  };
  require(cfg.k_normal > 0, "k_N must be > 0");
  require(!cfg.friction || cfg.k_tangential > 0, "k_T must be > 0 with friction");
  require(!cfg.friction || (cfg.mu_kinetic >= 0 && cfg.mu_static >= cfg.mu_kinetic),
          "friction needs 0 <= mu_k <= mu_s");
  require(cfg.restitution > 0 && cfg.restitution <= 1, "e must be in (0, 1]");
  require(cfg.steps_per_contact > 0, "steps_per_contact must be > 0");
  require(!(cfg.length_law && cfg.normal_law), "give normal_law or length_law, not both");
  law_ = cfg.length_law ? cfg.length_law.get() : cfg.normal_law.get();
  dof_ = {a_.dof_u, a_.dof_v, a_.dof_theta, b_.dof_u, b_.dof_v, b_.dof_theta};
  m_eff_ = isopound::effective_mass(a_.mass, b_.mass);
  xi_ = kelvin_voigt_xi(cfg.restitution);
  c_tangential_ = cfg.friction ? 2 * xi_ * std::sqrt(cfg.k_tangential * m_eff_) : 0.0;
  // Rotation ↔ displacement scale: the farthest vertex from the DOF origin of a body that turns.
  for (const PolygonBody* body : {&a_, &b_})
    if (body->dof_theta >= 0)
      for (const Vec2& p : body->shape.vertices())
        length_scale_ = std::max(length_scale_, length(p - body->p_WO));
  // The contact width w grows from 0 at a corner-first onset: bound it below in the step limit
  // by a quarter of the thinnest body's bounding box.
  double thinnest = std::numeric_limits<double>::infinity();
  for (const PolygonBody* body : {&a_, &b_}) {
    const Vec2 size = body->shape.box_max() - body->shape.box_min();
    thinnest = std::min({thinnest, size.x, size.y});
  }
  width_floor_ = 0.25 * thinnest;
  evaluate(committed_.q, committed_.qdot, true, committed_);
  compute_witness(committed_);
  trial_ = committed_;
}

PolygonContact::PolygonContact(std::string label, PolygonBody a, PolygonBody b,
                               const PolygonContactConfig& cfg, std::shared_ptr<PlanPair> pair,
                               int slot)
    : PolygonContact(std::move(label), std::move(a), std::move(b), cfg) {
  if (!pair || slot < 0 || slot >= pair->slots())
    throw std::invalid_argument("polygon contact '" + label_ + "': no such plan-pair slot");
  plan_pair_ = std::move(pair);
  slot_ = slot;
  evaluate(committed_.q, committed_.qdot, true, committed_);
  compute_witness(committed_);
  trial_ = committed_;
  report_committed();
}

Separation PolygonContact::separation_at(const Vec6& q) const {
  if (plan_pair_) return plan_pair_->separation(slot_, q);
  return separation_of(place(a_, q[0], q[1], q[2]), place(b_, q[3], q[4], q[5]));
}

Overlap PolygonContact::overlap_at(const ConvexPolygon& pa, const Vec6& q, Vec2 shift_B) const {
  Overlap ov;
  if (plan_pair_) {
    Vec6 shifted = q;
    shifted[3] += shift_B.x;
    shifted[4] += shift_B.y;
    ov = plan_pair_->overlap(slot_, shifted);
  } else {
    ov = overlap_of(pa, placed(b_, q[3] + shift_B.x, q[4] + shift_B.y, q[5]), cfg_.overlap);
  }
  orient_to_strip(ov, q[5]);
  return ov;
}

ConvexPolygon PolygonContact::place(const PolygonBody& body, double u, double v,
                                    double theta) const {
  // A fixed body (no DOF) stays where it is: no trigonometry.
  if (body.dof_u < 0 && body.dof_v < 0 && body.dof_theta < 0) return body.shape;
  return placed(body, u, v, theta);
}

ConvexPolygon PolygonContact::placed(const PolygonBody& body, double u, double v,
                                     double theta) const {
  const auto same = [](double a, double b) { return a == b && std::signbit(a) == std::signbit(b); };
  const int index = &body == &a_ ? 0 : 1;
  SharedPlacement* shared = shared_placement_[index].get();
  if (shared && shared->valid && same(shared->u, u) && same(shared->v, v) &&
      same(shared->theta, theta))
    return shared->polygon;
  Trig& t = trig_[index];
  if (!same(theta, t.theta)) t = {theta, std::cos(theta), std::sin(theta)};
  if (!shared) return body.shape.placed({u, v, theta}, body.p_WO, t.cos, t.sin);
  shared->polygon = body.shape.placed({u, v, theta}, body.p_WO, t.cos, t.sin);
  shared->valid = true;
  shared->u = u;
  shared->v = v;
  shared->theta = theta;
  return shared->polygon;
}

void PolygonContact::gather(const Eigen::VectorXd& x, Vec6& q) const {
  for (int k = 0; k < kDofs; ++k) q[k] = dof_[k] >= 0 ? x[dof_[k]] : 0.0;
}

// Pseudocode of the force law (committed state C, trial (q, q̇)):
//   place A, B by (u, v, θ); overlap → A_c, C, n, t, w, δ_N; status = geometry (or C's if frozen)
//   δ̇_N = (v_A(C) − v_B(C))·n;  F_N = k_N A_c + 2ξ√(k_N A_c/δ_N m_eff) δ̇_N, clamped at 0
//   Δu_T = (d_B(C) − d_A(C))·t, d = material displacement from the committed placement
//   s_tr = s_C + k_T Δu_T, f_tr = s_tr + c_T u̇_T; slip if |f_tr| > μ F_N (μ = μ_s from
//     stick, μ_k from slip): F_T = μ_k F_N sign(f_tr), s = sign(s_tr) min(|s_tr|, μ_k F_N);
//     else stick: s = s_tr, F_T = f_tr (option continuous_force: from stick the slip takes
//     μ_s F_N, and a frozen slip sticks if |f_tr| ≤ μ_k F_N; a forced status overrides)
//   on B: F = F_N n − F_T t at C; on A: −F; generalized forces with (C − O') × F.
void PolygonContact::evaluate(const Vec6& q, const Vec6& qdot, bool freeze, State& out) const {
  const State& C = committed_;
  out.q = q;
  out.qdot = qdot;
  out.witness_valid = false;
  out.differentiable = false;
  out.speed = -1.0;
  out.force.fill(0.0);
  out.area = out.indentation = out.width = 0.0;
  out.p_WC = out.n_AB = out.t_AB = Vec2{};
  out.rate_n = out.rate_t = out.raw_normal = out.elastic_normal = out.secant_width = 0.0;
  out.normal = out.tangential = out.spring = out.spring_trial = out.tangential_trial = 0.0;
  out.friction_dissipated = C.friction_dissipated;
  out.phase = C.phase;

  const Vec2 o_A = a_.p_WO + Vec2{q[0], q[1]}, o_B = b_.p_WO + Vec2{q[3], q[4]};
  const ConvexPolygon pa = place(a_, q[0], q[1], q[2]);
  const ConvexPolygon pb = place(b_, q[3], q[4], q[5]);
  // Lower bound of the distance apart (the larger axis gap of the bounding boxes), for the cheap
  // event test of far-apart pairs (event_fraction).
  out.box_gap =
      std::max(std::max(pb.box_min().x - pa.box_max().x, pa.box_min().x - pb.box_max().x),
               std::max(pb.box_min().y - pa.box_max().y, pa.box_min().y - pb.box_max().y));
  const auto open = [&] {
    // The tangential spring's energy is lost when a contact ends.
    if (C.closed && cfg_.friction)
      out.friction_dissipated += C.spring * C.spring / (2 * cfg_.k_tangential);
    out.closed = out.started = out.slipping = false;
  };
  // Boxes apart (overlap_of's own first test): no overlap, open unless frozen closed.
  if (out.box_gap > 0.0 && !(freeze && C.closed)) return open();
  Overlap ov = plan_pair_ ? plan_pair_->overlap(slot_, q) : overlap_of(pa, pb, cfg_.overlap);
  orient_to_strip(ov, q[5]);
  const bool overlapping = ov.area > 0.0;
  out.closed = freeze ? C.closed : overlapping;
  out.started = !freeze && !C.closed && overlapping;
  out.slipping = out.started ? false : C.slipping;
  if (!out.closed) return open();
  bool at_surface = false, own_shape = overlapping;
  const double sliver = kSurfaceSliver * length_scale_;
  const double actual_area = ov.area;
  const double overlap_width = length(ov.p_WP2 - ov.p_WP1);
  if (overlapping && ov.area < sliver * overlap_width) {
    // Shallower than the sliver: the shape (w, n, C) is taken from the sliver too, so that the
    // damping c_N ∝ √(A_c/δ_N) is continuous across A_c = 0. (An edge tilted by 1e-15 rad makes
    // a 1e-16 m² overlap a triangle with w ≪ L, while the at-surface sliver is the full face:
    // the two would differ ~10x in c_N, and Newton flips between them at a separation.)
    // (continuous_force: a sliver as deep as the overlap is short of it, so that the shape is
    // continuous where the overlap reaches the sliver's depth too.)
    const double deeper_by = cfg_.continuous_force ? sliver - ov.area / overlap_width : sliver;
    const Overlap shape = overlap_at(pa, q, -deeper_by * ov.n_AB);
    if (shape.area > 0.0) {
      ov = shape;
      own_shape = false;
    }
  }
  if (!overlapping) {
    // Frozen closed at the contact surface (a step cut to end at an onset or a separation ends
    // within round-off of A_c = 0, on either side): take the limit A_c → 0+, whose damping
    // force c_N δ̇_N is the Kelvin–Voigt jump. Its shape (w, n, C) is that of a sliver
    // kSurfaceSliver of the body size deep; its area counts as 0.
    if ((plan_pair_ ? separation_at(q) : separation_of(pa, pb)).distance > 1e-9 * length_scale_)
      return;  // apart: no force
    ov = surface_overlap(pa, pb, q, sliver);
    if (!(ov.area > 0.0)) return;
    at_surface = true;
  }

  out.area = at_surface ? 0.0 : actual_area;
  out.p_WC = ov.p_WC;
  out.n_AB = ov.n_AB;
  out.t_AB = ov.t_AB;
  out.width = length(ov.p_WP2 - ov.p_WP1);
  const bool thesis = cfg_.indentation == IndentationRule::kThesis;
  // A_c / δ_N: w (quadrilateral and up, or the mean-depth rule) or w/2 (triangle, thesis rule).
  out.triangle = hold_branch_ && C.closed ? C.triangle : ov.vertex_count == 3;
  const double area_per_depth = secant_width_of(ov, out.triangle);
  out.secant_width = area_per_depth;
  out.indentation = at_surface ? 0.0 : (thesis && out.triangle ? 2.0 : 1.0) * out.area / out.width;
  const Vec2 r_A = ov.p_WC - o_A, r_B = ov.p_WC - o_B;
  const Vec2 v_A = point_velocity(qdot[0], qdot[1], qdot[2], r_A);
  const Vec2 v_B = point_velocity(qdot[3], qdot[4], qdot[5], r_B);
  out.rate_n = dot(v_A - v_B, ov.n_AB);
  out.rate_t = dot(v_B - v_A, ov.t_AB);

  bool tension = cfg_.keep_tension;
  if (law_) {
    const ImpactLaw& law = *law_;
    const double scale = law_scale(area_per_depth);
    if (out.started) law.begin_contact(std::max(out.rate_n, 0.0), out.phase);
    out.raw_normal = scale * law.respond(out.indentation, out.rate_n, out.phase).force;
    out.elastic_normal = scale * law.respond(out.indentation, 0.0, out.phase).force;
    tension = tension || law.tension_allowed();
  } else {
    out.elastic_normal = cfg_.k_normal * out.area;
    const double c_n = 2 * xi_ * std::sqrt(cfg_.k_normal * area_per_depth * m_eff_);
    out.raw_normal = out.elastic_normal + c_n * out.rate_n;
  }
  out.normal = tension ? out.raw_normal : std::max(out.raw_normal, 0.0);

  if (cfg_.friction) {
    // Material displacement, committed → trial, of each body's point now at C.
    const auto displacement = [&](int k, Vec2 o_now, Vec2 p_WO) {
      const Vec2 o_then = p_WO + Vec2{C.q[k], C.q[k + 1]};
      return ov.p_WC - (o_then + rotate(ov.p_WC - o_now, C.q[k + 2] - q[k + 2]));
    };
    const double du_t = dot(displacement(3, o_B, b_.p_WO) - displacement(0, o_A, a_.p_WO), ov.t_AB);
    const double s_c = out.started ? 0.0 : C.spring;
    const double s_tr = s_c + cfg_.k_tangential * du_t;
    const double cap = cfg_.mu_kinetic * std::max(out.normal, 0.0);
    // Coulomb bounds the whole tangential force, dashpot included (THEORY-notes, "3D friction"):
    // the trial force f_tr = s_tr + c_T u̇_T decides stick or slip. Slipping, |F_T| = μ_k F_N
    // along f_tr and the spring is only ever lowered, s = sign(s_tr) min(|s_tr|, μ_k F_N); the
    // rest, F_T − s, has the sign of u̇_T, so it dissipates. Slip → stick is continuous.
    const double f_tr = s_tr + c_tangential_ * out.rate_t;
    const bool from_stick = !out.slipping;
    if (!freeze) {
      const double mu = out.slipping ? cfg_.mu_kinetic : cfg_.mu_static;
      out.slipping = std::abs(f_tr) > mu * std::max(out.normal, 0.0);
    } else if (out.slipping && cfg_.continuous_force) {
      out.slipping = std::abs(f_tr) > cap;
    }
    if (forced_friction_ != FrictionStatus::kFree)
      out.slipping = forced_friction_ == FrictionStatus::kSlip;
    if (out.slipping) {
      const double limit =
          cfg_.continuous_force && from_stick ? cfg_.mu_static * std::max(out.normal, 0.0) : cap;
      out.spring = sign_or_zero(s_tr) * std::min(std::abs(s_tr), limit);
      out.tangential = sign_or_zero(f_tr) * limit;
    } else {
      out.spring = s_tr;
      out.tangential = f_tr;
    }
    out.spring_trial = s_tr;
    out.tangential_trial = f_tr;
    // Tangential dissipation of the step: the work of F_T on the sliding, by the midpoint rule
    // (F_T,C + F_T)/2 · Δu_T, minus the change of the spring's s²/(2k_T). Spring–slider alone
    // this is (s_C + s)(s_tr − s)/(2k_T): μ_k F_N Δu_T in a steady slip, 0 in a dashpot-free
    // stick; the tangential dashpot's c_T u̇_T² is counted here too (friction, not impact).
    const double f_c = out.started ? 0.0 : C.tangential;
    out.friction_dissipated += 0.5 * (f_c + out.tangential) * du_t -
                               (out.spring * out.spring - s_c * s_c) / (2 * cfg_.k_tangential);
  }

  const Vec2 f_B = out.normal * ov.n_AB - out.tangential * ov.t_AB;  // on B
  // f_e is the restoring force (−the force on the body).
  out.force = {f_B.x, f_B.y, cross(r_A, f_B), -f_B.x, -f_B.y, -cross(r_B, f_B)};

  // What differentiate() follows: the area law of this overlap's own two-crossings shape.
  const bool strip = cfg_.strip_compression_W.x != 0.0 || cfg_.strip_compression_W.y != 0.0;
  if (cfg_.analytic_tangent && own_shape && !law_ && !plan_pair_ && !strip && ov.sources_known &&
      ov.kind == OverlapCase::kTwoCrossings && ov.chord_entry >= 0) {
    out.differentiable = true;
    out.topology_count = ov.vertex_count;
    out.chord_entry = ov.chord_entry;
    out.chord_exit = ov.chord_exit;
    std::copy_n(ov.sources.begin(), ov.vertex_count, out.topology.begin());
  }
}

void PolygonContact::compute_witness(State& s) const {
  const auto separation = [&](double tau) {
    Vec6 q;
    for (int k = 0; k < kDofs; ++k) q[k] = s.q[k] + tau * s.qdot[k];
    return separation_at(q).distance;
  };
  s.witness = -separation(0.0);
  // Rate by a central difference along the motion, the points moving ~1e-7 m.
  double speed = 0.0;
  for (int k = 0; k < kDofs; ++k)
    speed = std::max(speed, std::abs(s.qdot[k]) * (k % 3 == 2 ? length_scale_ : 1.0));
  if (speed > 0) {
    const double tau = 1e-7 / speed;
    s.witness_rate = -(separation(tau) - separation(-tau)) / (2 * tau);
    // A slot's witness jumps where a part of the overlap changes hands (plan_pair.h): a
    // difference across such a jump is no rate; no point of the bodies moves faster than the
    // speed bound.
    if (plan_pair_) s.witness_rate = std::clamp(s.witness_rate, -speed_of(s), speed_of(s));
  } else {
    s.witness_rate = 0.0;
  }
  s.witness_valid = true;
}

Overlap PolygonContact::surface_overlap(const ConvexPolygon& pa, const ConvexPolygon& pb,
                                        const Vec6& q, double sliver) const {
  const Separation sep = plan_pair_ ? separation_at(q) : separation_of(pa, pb);
  const double shift = std::max(sep.distance, 0.0) + sliver;
  return overlap_at(pa, q, -shift * sep.n_AB);
}

void PolygonContact::orient_to_strip(Overlap& ov, double theta_B) const {
  const Vec2 n0 = cfg_.strip_compression_W;
  if ((n0.x == 0.0 && n0.y == 0.0) || ov.vertex_count == 0) return;
  const Vec2 n = b_.dof_theta >= 0 ? rotate(n0, theta_B) : n0;
  const Vec2 t{-n.y + 0.0, n.x + 0.0};
  double lo = dot(t, ov.vertices[0]), hi = lo;
  for (int k = 1; k < ov.vertex_count; ++k) {
    lo = std::min(lo, dot(t, ov.vertices[k]));
    hi = std::max(hi, dot(t, ov.vertices[k]));
  }
  const Vec2 on_line = ov.vertex_count >= 3 ? ov.p_WC : ov.vertices[0];
  const double c = dot(t, on_line);
  ov.n_AB = n;
  ov.t_AB = t;
  ov.p_WP1 = on_line + (lo - c) * t;
  ov.p_WP2 = on_line + (hi - c) * t;
}

double PolygonContact::secant_width_of(const Overlap& ov) const {
  return secant_width_of(ov, ov.vertex_count == 3);
}

double PolygonContact::secant_width_of(const Overlap& ov, bool triangle) const {
  const double w = length(ov.p_WP2 - ov.p_WP1);
  return cfg_.indentation == IndentationRule::kThesis && triangle ? 0.5 * w : w;
}

double PolygonContact::speed_bound(const Vec6& qdot) const {
  double v = 0.0;
  for (int body = 0; body < 2; ++body)
    v += std::hypot(qdot[3 * body], qdot[3 * body + 1]) +
         std::abs(qdot[3 * body + 2]) * length_scale_;
  return v;
}

double PolygonContact::speed_of(const State& s) const {
  if (s.speed < 0.0) s.speed = speed_bound(s.qdot);
  return s.speed;
}

double PolygonContact::area_contact_step(double secant_width) const {
  const double k_sec = cfg_.k_normal * std::max(secant_width, width_floor_);
  return std::numbers::pi * std::sqrt(m_eff_ / k_sec) / cfg_.steps_per_contact;
}

double PolygonContact::trial_witness() const {
  if (trial_.witness_valid && !plan_pair_) return trial_.witness;
  State copy = trial_;
  compute_witness(copy);
  return copy.witness;
}

double PolygonContact::trial_depth() const {
  const Vec6& q = trial_.q;
  return -separation_at(q).distance;
}

void PolygonContact::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  Vec6 q, qdot;
  gather(u, q);
  gather(v, qdot);
  evaluate(q, qdot, freeze_, trial_);
  const State& C = committed_;
  double p0 = 0.0, p1 = 0.0;
  for (int k = 0; k < kDofs; ++k) {
    p0 += C.force[k] * C.qdot[k];
    p1 += trial_.force[k] * trial_.qdot[k];
  }
  trial_.work = C.work + 0.5 * h_ * (p0 + p1);
  trial_.gross_work = C.gross_work + 0.5 * h_ * (std::abs(p0) + std::abs(p1));
  if (trial_.started) {  // an episode starts with this step (its power at the start is 0)
    trial_.episode_work = C.work;
    trial_.episode_gross_work = C.gross_work;
  }
  // E_N = ∫ F_el dδ_N along the path (trapezoid in time), from 0 at each onset.
  trial_.normal_energy =
      trial_.closed
          ? (trial_.started ? 0.0 : C.normal_energy) +
                0.5 * h_ * (C.elastic_normal * C.rate_n + trial_.elastic_normal * trial_.rate_n)
          : 0.0;
}

void PolygonContact::add_force(Eigen::VectorXd& f) const {
  for (int k = 0; k < kDofs; ++k)
    if (dof_[k] >= 0) f[dof_[k]] += trial_.force[k];
}

// Pseudocode: column j of df/du + velocity_factor df/dv is the derivative of the force law along
// (e_j, velocity_factor e_j) on the trial's branch: by differentiate() (three columns a pass)
// where the trial is State::differentiable; else the central difference along (u, v) ±
// ε (e_j, velocity_factor e_j), ε ~ 1e-3 δ_N within [1e-10, 1e-7] m (a rotation scaled by the
// body size), return map and clamps included (accurate to ~1e-8 relative away from switches).
// differentiate() fails for a trial or succeeds for every column, so K never gets both.
void PolygonContact::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  if (!trial_.closed) return;  // (closed at A_c = 0: the damping limit still has a tangent)
  if (trial_.differentiable) {
    // Column j: the derivative along (e_j, velocity_factor e_j), three DOFs at a time.
    std::array<Vec6, 3> dq{}, dqdot{}, df{};
    std::array<int, 3> column{};
    int count = 0;
    const auto flush = [&] {
      for (int k = count; k < 3; ++k) dq[k].fill(0.0), dqdot[k].fill(0.0);
      if (!differentiate<3>(dq, dqdot, df)) return false;
      for (int k = 0; k < count; ++k)
        for (int i = 0; i < kDofs; ++i)
          if (dof_[i] >= 0) K(dof_[i], dof_[column[k]]) += df[k][i];
      count = 0;
      dq = {};
      dqdot = {};
      return true;
    };
    bool done = true;
    for (int j = 0; j < kDofs && done; ++j) {
      if (dof_[j] < 0) continue;
      dq[count][j] = 1.0;
      dqdot[count][j] = velocity_factor;
      column[count++] = j;
      if (count == 3) done = flush();
    }
    if (done && count > 0) done = flush();
    if (done) return;
  }
  const double eps_u = std::clamp(1e-3 * trial_.indentation, 1e-10, 1e-7);
  State plus, minus;
  for (int j = 0; j < kDofs; ++j) {
    if (dof_[j] < 0) continue;
    const double eps = j % 3 == 2 ? eps_u / length_scale_ : eps_u;
    Vec6 qp = trial_.q, qm = trial_.q, vp = trial_.qdot, vm = trial_.qdot;
    qp[j] += eps;
    qm[j] -= eps;
    vp[j] += velocity_factor * eps;
    vm[j] -= velocity_factor * eps;
    // Evaluate with the status the trial has (an onset in this trial stays an onset).
    evaluate(qp, vp, freeze_, plus);
    evaluate(qm, vm, freeze_, minus);
    for (int i = 0; i < kDofs; ++i)
      if (dof_[i] >= 0) K(dof_[i], dof_[j]) += (plus.force[i] - minus.force[i]) / (2 * eps);
  }
}

// Pseudocode: where the trial is differentiable, y += df/du x by differentiate() along x. Else
// the displacements move by ± s x, s such that the largest DOF moves by add_tangent's ε (a
// rotation scaled by the body size); y += (f(+) − f(−)) / (2s) on the element's DOFs.
void PolygonContact::add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (!trial_.closed) return;
  if (trial_.differentiable) {
    std::array<Vec6, 1> dq{}, dqdot{}, df{};
    for (int j = 0; j < kDofs; ++j)
      if (dof_[j] >= 0) dq[0][j] = x[dof_[j]];
    if (differentiate<1>(dq, dqdot, df)) {
      for (int i = 0; i < kDofs; ++i)
        if (dof_[i] >= 0) y[dof_[i]] += df[0][i];
      return;
    }
  }
  Vec6 dx{};
  double size = 0.0;
  for (int j = 0; j < kDofs; ++j) {
    if (dof_[j] < 0) continue;
    dx[j] = x[dof_[j]];
    size = std::max(size, std::abs(dx[j]) * (j % 3 == 2 ? length_scale_ : 1.0));
  }
  if (size == 0.0) return;
  const double eps_u = std::clamp(1e-3 * trial_.indentation, 1e-10, 1e-7);
  const double s = eps_u / size;
  Vec6 qp = trial_.q, qm = trial_.q;
  for (int j = 0; j < kDofs; ++j) {
    qp[j] += s * dx[j];
    qm[j] -= s * dx[j];
  }
  State plus, minus;
  evaluate(qp, trial_.qdot, freeze_, plus);
  evaluate(qm, trial_.qdot, freeze_, minus);
  for (int i = 0; i < kDofs; ++i)
    if (dof_[i] >= 0) y[dof_[i]] += (plus.force[i] - minus.force[i]) / (2 * s);
}

double PolygonContact::power(const Eigen::VectorXd& v) const {
  double p = 0.0;
  for (int k = 0; k < kDofs; ++k)
    if (dof_[k] >= 0) p += trial_.force[k] * v[dof_[k]];
  return p;
}

double PolygonContact::trial_stored() const {
  if (!trial_.closed) return 0.0;
  const double spring =
      cfg_.friction ? trial_.spring * trial_.spring / (2 * cfg_.k_tangential) : 0.0;
  return trial_.normal_energy + spring;
}

double PolygonContact::stored_energy() const {
  return trial_stored();
}

void PolygonContact::commit() {
  // (The witness is computed when an event test or an onset needs it, not here.)
  const State& C = committed_;
  if (trial_.started) {  // an onset no event located (events off, or within the tolerance)
    count_impact(std::max(trial_.rate_n, 0.0));
  } else if (cfg_.impact_count == ImpactCount::kForcePulses && C.closed && trial_.closed &&
             C.normal == 0.0 && C.raw_normal < 0.0 && trial_.normal > 0.0 &&
             trial_.rate_n >= kCountedImpactVelocity) {
    // A closed contact whose F_N was clamped at 0 (no force, the bodies still overlapping)
    // loads again while approaching: a new force pulse, as if it had opened (THEORY-notes).
    count_impact(trial_.rate_n);
  }
  if (trial_.closed) {
    (trial_.slipping ? time_slip_ : time_stick_) += h_;
  }
  if (C.closed && !trial_.closed) end_episode(trial_);  // a separation no event located
  if (h_ > 0) {
    // |δ̈| is bounded by the bodies' accelerations: the speed bound of the change of rates.
    Vec6 change;
    for (int k = 0; k < kDofs; ++k) change[k] = trial_.qdot[k] - C.qdot[k];
    rate_change_ = speed_bound(change) / h_;
  }
  if (trial_.started) contact_step_ = onset_contact_step(trial_);
  steps_in_contact_ = trial_.started ? 0 : steps_in_contact_ + 1;
  trial_.started = false;
  friction_dissipated_ = trial_.friction_dissipated;
  committed_ = trial_;
  approach_cached_ = false;
  report_committed();
}

void PolygonContact::count_impact(double approach_rate) {
  ++impacts_;
  max_impact_velocity_ = std::max(max_impact_velocity_, approach_rate);
  if (approach_rate >= kCountedImpactVelocity) ++impacts_above_1mm_s_;
}

double PolygonContact::onset_contact_step(const State& s) const {
  if (law_)
    return contact_period_estimate(*law_, s.phase, law_mass(s.secant_width)) /
           cfg_.steps_per_contact;
  return area_contact_step(s.secant_width);
}

// The net work of the contact forces on the structures over the episode is −(W_sep − W_onset).
void PolygonContact::end_episode(const State& s) {
  episode_work_.end(-(s.work - s.episode_work), s.gross_work - s.episode_gross_work);
}

void PolygonContact::revert() {
  trial_ = committed_;
}

double PolygonContact::event_fraction() {
  State& C = committed_;
  State& T = trial_;
  double theta = 1.0;
  pending_ = Event::kNone;
  // A plan-pair slot's witness depends on the other slots' status too: never kept across calls.
  if (plan_pair_) C.witness_valid = T.witness_valid = false;
  // Far apart at both ends of the step: no onset inside it. The Hermite witness between the
  // ends lies below max(w_0, w_1) + 0.15 h (|ẇ_0| + |ẇ_1|) (the cubic's first-derivative
  // basis peaks at 4/27), and |ẇ| is at most the bodies' speed bound; so a box gap larger than
  // h (speed_C + speed_T) at both ends excludes a crossing without the three separation_of
  // calls of the witness.
  const double margin = h_ * (speed_of(C) + speed_of(T)) + 1e-9 * length_scale_;
  const bool far = !C.closed && !T.closed && C.box_gap > margin && T.box_gap > margin;
  if (!far) {
    if (!C.witness_valid) compute_witness(C);
    if (!T.witness_valid) compute_witness(T);
  }
  const auto consider = [&](double f, Event kind, bool inside_only) {
    const bool inside = f > kInsideEventFraction && f < 1.0 - kInsideEventFraction;
    if ((!inside_only || inside) && f < theta) {
      theta = std::max(f, 0.0);
      pending_ = kind;
    }
  };
  if (!far) {
    const WitnessStep w{C.witness, C.witness_rate, T.witness, T.witness_rate, h_};
    const double f = first_status_change(w, C.closed);
    if (f < 1.0) consider(f, C.closed ? Event::kSeparation : Event::kOnset, false);
  }
  if (C.closed && T.closed && cfg_.friction && !C.slipping && T.slipping) {
    // Stick → slip: the force drops from μ_s F_N to μ_k F_N. Linear in the excess.
    const double g0 = std::abs(C.tangential) - cfg_.mu_static * C.normal;
    const double g1 = std::abs(T.tangential_trial) - cfg_.mu_static * T.normal;
    consider(g0 >= 0 ? 0.0 : std::min(g0 / (g0 - g1), 1.0 - 1e-15), Event::kSlip, false);
  }
  // The approach → restitution switch (δ̇_N = 0) ends a step, as in the 2D contact: a kink of
  // the laws with a damper in approach only (normal_law option); harmless for the area law.
  if (C.closed && T.closed && C.rate_n > 0 && T.rate_n <= 0)
    consider(C.rate_n / (C.rate_n - T.rate_n), Event::kPhase, true);
  const bool tension = cfg_.keep_tension || (law_ && law_->tension_allowed());
  if (!tension && C.closed && T.closed && C.raw_normal > 0 && T.raw_normal < 0)
    consider(C.raw_normal / (C.raw_normal - T.raw_normal), Event::kTension, true);
  return theta;
}

bool PolygonContact::pending_has_indicator() const {
  return pending_ == Event::kTension || pending_ == Event::kPhase || pending_ == Event::kSlip;
}

double PolygonContact::event_indicator(bool committed) const {
  const State& S = committed ? committed_ : trial_;
  switch (pending_) {
    case Event::kTension:
      return S.raw_normal;
    case Event::kPhase:
      return S.rate_n;
    case Event::kSlip:  // the committed state's |F_T|, the trial's |f_tr|, as event_fraction
      return cfg_.mu_static * S.normal - std::abs(committed ? S.tangential : S.tangential_trial);
    default:
      return 0.0;
  }
}

bool PolygonContact::settle_event() {
  State& C = committed_;
  const Event event = pending_;
  if (plan_pair_) C.witness_valid = false;
  pending_ = Event::kNone;
  switch (event) {
    case Event::kOnset: {
      if (C.closed) return false;
      C.closed = true;
      C.slipping = false;
      C.spring = 0.0;
      C.normal_energy = 0.0;
      if (!C.witness_valid) compute_witness(C);
      C.episode_work = C.work;
      C.episode_gross_work = C.gross_work;
      const double v_imp = std::max(C.witness_rate, 0.0);
      if (law_) law_->begin_contact(v_imp, C.phase);
      // The contact's state at its onset (the limit A_c → 0+): its shape sets the first contact
      // step, and Coulomb decides whether it starts sliding: a slab that arrives sliding along
      // the other body at u̇_T has f_tr = c_T u̇_T against μ_s F_N (without this test the frozen
      // status "stick" let c_T u̇_T act unbounded at the onset: 17 MN against F_N = 7 MN, seen
      // between adjacent floors).
      State at_onset;
      evaluate(C.q, C.qdot, true, at_onset);
      C.secant_width = at_onset.secant_width;
      if (cfg_.friction)
        C.slipping =
            std::abs(at_onset.tangential_trial) > cfg_.mu_static * std::max(at_onset.normal, 0.0);
      count_impact(v_imp);
      contact_step_ = onset_contact_step(C);
      steps_in_contact_ = 0;
      break;
    }
    case Event::kSeparation:
      if (!C.closed) return false;
      end_episode(C);
      if (cfg_.friction) C.friction_dissipated += C.spring * C.spring / (2 * cfg_.k_tangential);
      C.closed = C.slipping = false;
      C.spring = C.normal_energy = 0.0;
      break;
    case Event::kSlip: {
      if (!C.closed || C.slipping) return false;
      const double s = sign_or_zero(C.spring) *
                       std::min(std::abs(C.spring), cfg_.mu_kinetic * std::max(C.normal, 0.0));
      C.friction_dissipated += (C.spring * C.spring - s * s) / (2 * cfg_.k_tangential);
      C.spring = s;
      C.slipping = true;
      break;
    }
    case Event::kTension:
    case Event::kPhase:
    case Event::kNone:
      return false;  // the force is continuous there
  }
  friction_dissipated_ = C.friction_dissipated;
  trial_ = C;
  approach_cached_ = false;
  report_committed();
  return true;
}

// Closed: a fraction of the contact period π √(m_eff δ_N / F_el) = π √(m_eff / k_sec), the
// secant stiffness k_sec = k_N A_c/δ_N = k_N w (triangle: k_N w/2) with w ≥ width_floor_,
// graded from the onset as the 2D contact's (contact_step.h). Open: approach_limit().
double PolygonContact::step_limit() const {
  const State& C = committed_;
  if (!C.closed) return approach_limit();
  double limit = 1e300;
  if (law_) {
    const double delta = std::max(C.indentation, 1e-3);
    const double k_sec = law_->respond(delta, 0.0, C.phase).force / delta;
    if (k_sec > 0)
      limit =
          std::numbers::pi * std::sqrt(law_mass(C.secant_width) / k_sec) / cfg_.steps_per_contact;
  } else {
    limit = area_contact_step(C.secant_width);
  }
  return std::min(graded_contact_step(contact_step_, steps_in_contact_), limit);
}

// Pseudocode (as Contact1D's, on the witness −separation): the time of impact from the
// separation d, its rate and |δ̈| ≤ 2 rate_change_; at most that, but never below the contact
// step at arrival (the area law's from the width of the sliver the contact would start with).
// A cheap lower bound first: the bounding boxes' gap (≤ the separation) closed at the bodies'
// speed bound (≥ the witness rate). When even that exceeds twice the longest step tried, no
// step can reach it and the witness is not needed: the steps are the same as with it.
double PolygonContact::approach_limit() const {
  if (approach_cached_ && !plan_pair_) return approach_limit_;
  const State& C = committed_;
  const double acceleration_bound = 2.0 * rate_change_;
  const TimeOfImpact far = time_of_impact(C.box_gap, speed_of(C), acceleration_bound);
  approach_cached_ = true;
  if (far.time >= 2.0 * longest_step_) return approach_limit_ = far.time;
  State s = C;
  if (!s.witness_valid || plan_pair_) compute_witness(s);
  const TimeOfImpact toi = time_of_impact(-s.witness, s.witness_rate, acceleration_bound);
  if (toi.time >= 1e300) return approach_limit_ = 1e300;
  double floor = 0.0;
  if (law_) {
    ImpactPhase phase;
    law_->begin_contact(std::max(toi.arrival_speed, kCountedImpactVelocity), phase);
    // A length law's contact length at arrival is at most body B's longest side.
    const Vec2 size = b_.shape.box_max() - b_.shape.box_min();
    const double length = cfg_.length_law ? std::max(size.x, size.y) : 1.0;
    floor = contact_period_estimate(*law_, phase, m_eff_ / length) / cfg_.steps_per_contact;
  } else if (toi.time < area_contact_step(0.0)) {  // the floor's largest value (w = width_floor_)
    const ConvexPolygon pa = place(a_, C.q[0], C.q[1], C.q[2]);
    const ConvexPolygon pb = place(b_, C.q[3], C.q[4], C.q[5]);
    const Overlap ov = surface_overlap(pa, pb, C.q, kSurfaceSliver * length_scale_);
    floor = area_contact_step(ov.area > 0.0 ? secant_width_of(ov) : 0.0);
  }
  return approach_limit_ = std::max(toi.time, floor);
}

ContactSnapshot PolygonContact::snapshot() const {
  const State& T = trial_;
  return {T.closed, T.closed && T.slipping, T.area, T.indentation,
          T.normal, T.tangential,           T.p_WC, T.n_AB,
          T.t_AB};
}

std::string PolygonContact::output_name(int i) const {
  static const char* kNames[kOutputCount] = {"normal_force",
                                             "tangential_force",
                                             "area",
                                             "indentation",
                                             "impacts",
                                             "impact_velocity",
                                             "slipping",
                                             "time_in_stick",
                                             "time_in_slip",
                                             "friction_dissipated_energy",
                                             "impact_dissipated_energy",
                                             "in_contact"};
  return kNames[i];
}

std::string PolygonContact::output_unit(int i) const {
  static const char* kUnits[kOutputCount] = {"N", "N", "m2", "m", "-", "m/s",
                                             "-", "s", "s",  "J", "J", "-"};
  return kUnits[i];
}

Element::OutputKind PolygonContact::output_kind(int i) const {
  if (i == 4) return OutputKind::kCount;             // impacts
  if (i == 6 || i == 11) return OutputKind::kState;  // slipping, in_contact
  return OutputKind::kContinuous;
}

void PolygonContact::outputs(double* out) const {
  const State& T = trial_;
  out[0] = T.normal;
  out[1] = T.tangential;
  out[2] = T.area;
  out[3] = T.indentation;
  out[4] = impacts_ + (T.started ? 1 : 0);
  out[5] = std::max(max_impact_velocity_, T.started ? std::max(T.rate_n, 0.0) : 0.0);
  out[6] = T.closed && T.slipping ? 1.0 : 0.0;
  out[7] = time_stick_;
  out[8] = time_slip_;
  out[9] = T.friction_dissipated;
  out[10] = T.work - trial_stored() - T.friction_dissipated;
  out[11] = T.closed ? 1.0 : 0.0;
}

double PolygonContact::output(int i) const {
  double values[kOutputCount];
  outputs(values);
  return values[i];
}

}  // namespace isopound
