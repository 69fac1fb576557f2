// 3D pounding between two rigid diaphragms in plan (THEORY §6): force from the overlap of their
// convex polygons, F_N = k_N A_c + c_N δ̇_N at the overlap centroid C, Coulomb by a return map.
// Signs: n_AB from A into B; the force on B is F_N n_AB − F_T t_AB, on A its opposite; torques
// (p_WC − p_WO) × F about each body's DOF origin O (which moves with the body). THEORY-notes.md.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <string>

#include "geometry/overlap.h"
#include "solver/core/element.h"
#include "solver/elements/episode_work.h"
#include "solver/elements/plan_pair.h"
#include "solver/materials/impact_law.h"

namespace isopound {

// The last placement of one body's outline, shared by the contacts of that body (a slab and its
// four moat walls place the same slab at the same trial): computed by the first, copied by the
// rest. Exactly what each would compute (a pure function of (u, v, θ)).
struct SharedPlacement {
  explicit SharedPlacement(const ConvexPolygon& outline) : polygon(outline) {}
  bool valid = false;
  double u = 0.0, v = 0.0, theta = 0.0;
  ConvexPolygon polygon;
};

// One body of a polygon contact: a rigid diaphragm with DOFs (u, v, θ) taken at the point O, or
// a fixed body (all three DOF indices −1), or any subset (a missing DOF stays at 0).
struct PolygonBody {
  int dof_u = -1;       // DOF index of the translation along x, or −1
  int dof_v = -1;       // along y, or −1
  int dof_theta = -1;   // of the rotation (rad, counter-clockwise), or −1
  Vec2 p_WO;            // the DOF origin O at rest, plan frame W, m
  ConvexPolygon shape;  // plan outline at rest, plan frame W, m (placed by (u, v, θ) about O)
  double mass = 0.0;    // kg, for m_eff (a fixed wall: its given mass; +inf allowed)
};

// Normal and tangential stiffness from the materials (thesis eq. 5.23–5.26), E_st in Pa:
// E_dyn = 5.82 E_st^0.63 (E in GPa), G_dyn = E_dyn / (2(1 + ν)),
// k_N = ((1 − ν₁²)/E_dyn,1 + (1 − ν₂²)/E_dyn,2)⁻¹ (N/m²), k_T = ((2 − ν₁)/G₁ + (2 − ν₂)/G₂)⁻¹
// (N/m).
struct ContactStiffness {
  double k_normal = 0.0;      // N/m² (force per overlap area)
  double k_tangential = 0.0;  // N/m
};
ContactStiffness contact_stiffness_from_materials(double e_static_1, double nu_1, double e_static_2,
                                                  double nu_2);

// How δ_N enters c_N = 2ξ √((k_N A_c / δ_N) m_eff).
enum class IndentationRule {
  kThesis,     // eq. 5.20: 2A_c/w for a triangle, A_c/w otherwise (jumps ×2 at tri → quad)
  kMeanDepth,  // A_c/w always (continuous)
};

// How impacts are counted (THEORY-notes, "3D contact": what an impact is).
enum class ImpactCount {
  kForcePulses,  // overlap onsets, and reloadings of a force-free closed contact (default)
  kOnsets,       // overlap onsets only
};

struct PolygonContactConfig {
  double k_normal = 2.58e10;     // N/m²
  double k_tangential = 5.74e9;  // N/m
  double mu_static = 0.8;        // μ_s: stick while |s| ≤ μ_s F_N
  double mu_kinetic = 0.6;       // μ_k: |F_T| = μ_k F_N while slipping
  double restitution = 0.65;     // e → ξ by Kelvin–Voigt (eq. 3.7)
  bool friction = true;          // false: no tangential force at all
  bool keep_tension = false;     // true: a tensile F_N is applied (KV as published)
  IndentationRule indentation = IndentationRule::kThesis;
  OverlapMethod overlap = OverlapMethod::kFast;
  double steps_per_contact = 100;  // step limit in contact: T_c / steps_per_contact
  // The force continuous in the placement (struck columns: a massless node cannot balance a
  // jump). Friction: from stick, a slipping trial takes mu_s F_N, the stick limit (such a trial
  // always ends at its located stick-slip event, where the drop to mu_k F_N is settled); frozen
  // in slip (a step cut at an event, a restart), the trial may stick (|f_tr| <= mu_k F_N), as
  // unfrozen. Shallower than the sliver, the shape (w, n, C) of an overlap as deep as the sliver
  // (not of one a sliver deeper). False: mu_k F_N from stick, a frozen slip stays slip
  // (mu_k F_N sign(f_tr)), and the shape jumps where the overlap reaches the sliver's depth.
  bool continuous_force = false;
  // What counts as an impact (impacts(), impacts_above_1mm_s()): every onset of a compressive
  // normal force pulse (kForcePulses: an onset of overlap, and a closed contact whose F_N was
  // clamped at 0 loading again while approaching), or overlap onsets only (kOnsets).
  ImpactCount impact_count = ImpactCount::kForcePulses;
  // The Newton tangent and the error estimate's stiffness product (THEORY-notes, "3D contact
  // tangent"): true, by forward-mode differentiation of the force law on the trial's branch,
  // its overlap's topology held (exact to round-off), wherever the law is the area law of two
  // convex outlines crossing at two points; elsewhere (and false) by central differences of
  // the force law.
  bool analytic_tangent = true;
  // Option: one of the ten 2D impact laws along the normal with δ_N as the penetration
  // (its k in N/m); null = the area law k_N A_c + c_N δ̇_N.
  std::shared_ptr<const ImpactLaw> normal_law;
  // Option (issue 27, rubber bumpers): a law of the force per unit contact length along the
  // normal, F_N = L_c f(δ_N, δ̇_N) with L_c = A_c/δ_N the overlap's secant width (its k in N/m
  // per m of contact; a linear f = k δ_N is the area law k A_c without damping). Not with
  // normal_law.
  std::shared_ptr<const ImpactLaw> length_law;
  // A rubber strip as body B (a bumper's contact, with length_law): the unit direction B is
  // compressed along at rest, plan frame W, from body A into the face that carries the strip; it
  // turns with B. The contact's normal is this direction, not the overlap's chord: a strip that
  // ends inside the striking face and is pressed through its whole depth has its chord across
  // the strip, whose normal would run along the face. Zero (every other contact): the chord's.
  Vec2 strip_compression_W;
};

// What a writer of the contact-event log needs at a step (SI, plan frame W).
struct ContactSnapshot {
  bool in_contact = false;
  bool slipping = false;
  double area = 0.0;              // A_c, m²
  double indentation = 0.0;       // δ_N, m
  double normal_force = 0.0;      // F_N, N (≥ 0 unless keep_tension)
  double tangential_force = 0.0;  // F_T, N: the force on B is F_N n_AB − F_T t_AB
  Vec2 p_WC;                      // action point C, m
  Vec2 n_AB;                      // unit normal from A into B
  Vec2 t_AB;                      // unit tangent, n_AB turned +90°
};

class PolygonContact final : public Element {
 public:
  PolygonContact(std::string label, PolygonBody a, PolygonBody b, const PolygonContactConfig& cfg);
  // One slot of a pair of plans of any outline (plan_pair.h): the overlap component `slot` of
  // `pair` is this contact's. a.shape and b.shape are the outlines' convex hulls (the bodies'
  // size and bounding boxes); the DOFs and p_WO as the pair's.
  PolygonContact(std::string label, PolygonBody a, PolygonBody b, const PolygonContactConfig& cfg,
                 std::shared_ptr<PlanPair> pair, int slot);

  // Body `body` (0: A, 1: B) shares its placements with the other contacts holding `shared`:
  // they must have the same DOFs, p_WO and shape.
  void share_placement(int body, std::shared_ptr<SharedPlacement> shared) {
    shared_placement_[body] = std::move(shared);
  }

  void begin_step(double h, bool freeze_status) override {
    h_ = h;
    longest_step_ = std::max(longest_step_, h);
    freeze_ = freeze_status;
  }
  // Held: a closed contact keeps its committed overlap shape's δ_N rule (eq. 5.20: triangle or
  // not), whose c_N jumps by √2 where a triangle overlap becomes a quadrilateral.
  void hold_branch(bool hold) override { hold_branch_ = hold; }
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  // The thesis force acts at C along the chord normal: not the gradient of a potential once
  // the bodies rotate, so the tangent is non-symmetric even without friction.
  bool add_dofs(std::vector<int>& dofs) const override {
    for (const int d : dof_)
      if (d >= 0) dofs.push_back(d);
    return true;
  }
  bool symmetric_tangent() const override { return false; }
  // y += K x (stiffness, velocity factor 0), the stepper's error estimate: the derivative along
  // x by differentiate() where add_tangent differentiates, else one central difference along x
  // (2 force evaluations instead of 2 per DOF, equal to add_tangent's columns times x to their
  // truncation error).
  bool has_stiffness_product() const override { return true; }
  void add_stiffness_product(const Eigen::VectorXd& x, Eigen::VectorXd& y) const override;
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override;
  void commit() override;
  void revert() override;
  double event_fraction() override;
  bool settle_event() override;
  double step_limit() const override;

  int output_count() const override { return kOutputCount; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override;
  const std::string& label() const override { return label_; }

  // The trial state for an event log.
  ContactSnapshot snapshot() const;
  // By name, for tests (committed counters, trial forces).
  int impacts() const { return impacts_; }
  // Onsets with an impact velocity of at least 1 mm/s (grazing re-contacts left out), the
  // count the window-convergence check of issue 16 compares.
  int impacts_above_1mm_s() const { return impacts_above_1mm_s_; }
  double max_impact_velocity() const { return max_impact_velocity_; }
  // Passivity per contact episode (onset to separation): the net work of the contact forces on
  // the structures, −(W_sep − W_onset) with W the element work ∫ v·f_e dt. Completed episodes,
  // the largest net work of any of them (J; ≤ 0 for a passive contact, −inf before any), and that
  // episode's net work over its gross work ∫ |v·f_e| dt (the scale of its round-off).
  int episodes() const { return episode_work_.episodes(); }
  double max_episode_net_work() const { return episode_work_.max_net_work(); }
  double max_episode_net_work_relative() const { return episode_work_.max_net_work_relative(); }
  double friction_dissipated() const { return friction_dissipated_; }
  double trial_friction_dissipated() const { return trial_.friction_dissipated; }
  double dissipated_energy() const { return trial_.work - trial_stored(); }
  double effective_mass() const { return m_eff_; }
  const ImpactLaw* length_law() const { return cfg_.length_law.get(); }
  double normal_damping_ratio() const { return xi_; }
  // Witness (penetration −separation, m) and its rate (m/s) at the trial state.
  double trial_witness() const;
  // The trial state's status, approach rate δ̇_N (m/s, > 0 closing) and penetration depth (m,
  // −separation: continuous in the placement, 0 at touch; without the witness's rate).
  bool trial_closed() const { return trial_.closed; }
  // Whether add_tangent and add_stiffness_product differentiate the trial's force law (the
  // option analytic_tangent, at a two-crossings overlap of the area law), not difference it.
  bool trial_tangent_analytic() const { return trial_.closed && trial_.differentiable; }
  double trial_approach_rate() const { return trial_.rate_n; }
  double trial_depth() const;
  // The friction status of the trials from now on: the return map's (kFree), or forced to stick
  // (F_T = f_tr) or slip (F_T = mu F_N sign(f_tr)), each smooth in the placement. For a caller
  // that solves for a body through the nonsmooth return map by its two smooth branches (a struck
  // column's node), and sets it back to kFree before the trial is used.
  enum class FrictionStatus { kFree, kStick, kSlip };
  void force_friction_status(FrictionStatus status) { forced_friction_ = status; }

  // After event_fraction(): whether its event is one whose fraction interpolates a smooth
  // indicator linearly (no-tension clamp F_N = 0, approach/restitution switch, stick -> slip),
  // and that indicator at the committed (true) or trial state, > 0 before the event, < 0 after.
  // For a caller whose trials are not linear in the step (a massless node behind a dashpot)
  // and which finds the zero itself.
  bool pending_has_indicator() const;
  // The pending event only ends the step at a kink of a continuous force (no-tension, phase).
  bool pending_is_kink() const { return pending_ == Event::kTension || pending_ == Event::kPhase; }
  double event_indicator(bool committed) const;

  enum { kOutputCount = 12 };

 private:
  static constexpr int kDofs = 6;  // (u, v, θ) of A then B
  using Vec6 = std::array<double, kDofs>;
  enum class Event { kNone, kOnset, kSeparation, kSlip, kTension, kPhase };

  // Everything the force depends on at one state (trial or committed).
  struct State {
    Vec6 q{}, qdot{};  // (u, v, θ) of A and B, and their rates
    bool closed = false;
    bool slipping = false;
    bool started = false;  // this trial began a contact (no event located)
    double area = 0.0, indentation = 0.0, width = 0.0;
    Vec2 p_WC, n_AB, t_AB;
    double rate_n = 0.0;          // δ̇_N: approach rate at C along n_AB, m/s (> 0 closing)
    double rate_t = 0.0;          // u̇_T: sliding rate of B on A at C along t_AB, m/s
    double secant_width = 0.0;    // A_c/δ_N of the overlap's shape (w, or w/2), m
    bool triangle = false;        // the overlap's shape takes eq. 5.20's triangle rule
    double raw_normal = 0.0;      // F_N before the no-tension clamp
    double elastic_normal = 0.0;  // k_N A_c (or the law's F(δ_N, 0))
    double normal = 0.0, tangential = 0.0;  // F_N, F_T as applied
    double spring = 0.0;                    // s, the tangential spring force after the return map
    double spring_trial = 0.0;              // s_tr, before it
    double tangential_trial = 0.0;          // f_tr = s_tr + c_T u̇_T, the stick/slip test
    Vec6 force{};             // f_e on (u, v, θ) of A, B (restoring sign: −force on body)
    double work = 0.0;        // ∫ v·f_e dt, J (trapezoid), from the start
    double gross_work = 0.0;  // ∫ |v·f_e| dt, J (trapezoid), from the start
    double episode_work = 0.0, episode_gross_work = 0.0;  // work, gross_work at this onset
    double normal_energy = 0.0;                // E_N = ∫ F_el δ̇_N dt in this contact, J
    double friction_dissipated = 0.0;          // Σ (s_tr² − s²)/(2 k_T), J
    double witness = 0.0, witness_rate = 0.0;  // −separation and its rate
    double box_gap =
        0.0;  // m, lower bound of the distance apart (bounding boxes), < 0 if they meet
    bool witness_valid = false;
    mutable double speed = -1.0;  // speed_bound(qdot) once asked (speed_of), else < 0
    ImpactPhase phase;            // the normal law's memory of this contact (option normal_law)
    // The force is the area law of this overlap itself (two crossings, no sliver's shape), whose
    // vertices' sources (topology_count of them) let differentiate() follow it.
    bool differentiable = false;
    int topology_count = 0, chord_entry = -1, chord_exit = -1;
    std::array<OverlapVertexSource, kMaxOverlapVertices> topology;
  };

  // The force law at (q, qdot) from the committed state; `out` gets everything but work.
  void evaluate(const Vec6& q, const Vec6& qdot, bool freeze, State& out) const;
  // Directional derivatives of the trial's force f_e along N directions (dq_k, dqdot_k) of
  // (q, qdot): df_k, by forward-mode differentiation of the force law on the trial's branch
  // (stick or slip, clamp, triangle rule) with its overlap's topology held
  // (polygon_contact_tangent.cpp). False, and nothing written, where the trial is not
  // State::differentiable or the option is off.
  template <int N>
  bool differentiate(const std::array<Vec6, N>& dq, const std::array<Vec6, N>& dqdot,
                     std::array<Vec6, N>& df) const;
  void gather(const Eigen::VectorXd& x, Vec6& q) const;
  // The body's outline placed by (u, v, θ); a fixed body (no DOF) stays where it is.
  ConvexPolygon place(const PolygonBody& body, double u, double v, double theta) const;
  // body.shape placed by (u, v, θ) about its DOF origin, cos θ and sin θ kept from the body's
  // last placement at the same θ (a trial's evaluations and most of its tangent's share one).
  ConvexPolygon placed(const PolygonBody& body, double u, double v, double theta) const;
  void compute_witness(State& s) const;
  // The signed separation of the pair at q: of the convex shapes, or of this slot (plan pair).
  Separation separation_at(const Vec6& q) const;
  // The overlap at q with B moved by shift_B: of the convex shapes, or this slot's (plan pair);
  // a strip's oriented to it (orient_to_strip).
  Overlap overlap_at(const ConvexPolygon& pa, const Vec6& q, Vec2 shift_B) const;
  // Tells the plan pair this slot's committed status (no-op for a convex pair).
  void report_committed() {
    if (plan_pair_) plan_pair_->set_committed(slot_, committed_.closed, committed_.q);
  }
  // The overlap of A and B moved together along their separation direction until B is a sliver
  // `sliver` deep inside A: the shape of a contact at A_c → 0+ (empty if they are far apart).
  Overlap surface_overlap(const ConvexPolygon& pa, const ConvexPolygon& pb, const Vec6& q,
                          double sliver) const;
  // Bound of the speed of any material point of the two bodies, relative to the other: Σ over
  // A and B of |(u̇, v̇)| + |θ̇| L (m/s; of accelerations times a step when given rate changes).
  double speed_bound(const Vec6& qdot) const;
  // speed_bound(s.qdot), computed once per state.
  double speed_of(const State& s) const;
  // A strip's overlap (PolygonContactConfig::strip_compression_W set): its normal turned to the
  // strip's compression direction at B's angle theta_B, the tangent +90° from it, P1, P2 the
  // overlap's extremes along the tangent on the line through its centroid (the contact takes
  // w = |P1P2| and δ_N from them; the geometry's own indentation fields are not read). Other
  // contacts: unchanged.
  void orient_to_strip(Overlap& ov, double theta_B) const;
  // A_c/δ_N of an overlap's shape under the configured indentation rule (w, or w/2).
  double secant_width_of(const Overlap& ov) const;
  double secant_width_of(const Overlap& ov, bool triangle) const;
  // The contact step of the area law at a secant width (m): π √(m_eff/(k_N w_s))/steps, w_s
  // bounded below by width_floor_.
  double area_contact_step(double secant_width) const;
  // Step limit while open: time of impact, floored by the contact step at arrival.
  double approach_limit() const;
  void count_impact(double approach_rate);
  // The contact step of a contact begun at state s (area law: at its secant width; a normal
  // law: its contact period at s's impact velocity).
  double onset_contact_step(const State& s) const;
  double trial_stored() const;
  // F_N = scale f(δ_N, δ̇_N) of the normal law (normal_law or length_law): scale 1, or the
  // contact length L_c = A_c/δ_N (the overlap's secant width).
  double law_scale(double secant_width) const { return cfg_.length_law ? secant_width : 1.0; }
  // The mass a contact period of the normal law sees: m_eff / L_c for a length law, L_c bounded
  // below by width_floor_ (a shorter period: the step limit errs small).
  double law_mass(double secant_width) const {
    return m_eff_ / (cfg_.length_law ? std::max(secant_width, width_floor_) : 1.0);
  }

  std::string label_;
  PolygonBody a_, b_;
  std::shared_ptr<PlanPair> plan_pair_;  // null: the convex shapes' own overlap
  int slot_ = 0;
  PolygonContactConfig cfg_;
  const ImpactLaw* law_ = nullptr;  // normal_law or length_law; null: the area law
  std::array<int, kDofs> dof_{};
  double m_eff_ = 0.0;
  double xi_ = 0.0;
  double c_tangential_ = 0.0;  // 2ξ √(k_T m_eff)
  double length_scale_ = 1.0;  // m, converts a rotation to a displacement (FD steps, witness)
  double width_floor_ = 0.0;   // m, lower bound of w in the step limit
  double h_ = 0.0;
  double longest_step_ = 0.0;  // s, the longest step tried so far (the analysis interval)
  bool freeze_ = false;
  bool hold_branch_ = false;
  FrictionStatus forced_friction_ = FrictionStatus::kFree;
  State committed_, trial_;
  struct Trig {
    double theta = 0.0, cos = 1.0, sin = 0.0;  // cos θ, sin θ as std::cos, std::sin give them
  };
  mutable std::array<Trig, 2> trig_{};                                // of a_ and b_
  std::array<std::shared_ptr<SharedPlacement>, 2> shared_placement_;  // of a_ and b_, or null
  double contact_step_ = 1e300;  // s, the contact step from the current contact's onset
  int steps_in_contact_ = 0;     // accepted steps since the current contact began
  double rate_change_ = 0.0;     // bound of |δ̈| over the last accepted step (kinematic), m/s²
  mutable bool approach_cached_ = false;  // approach_limit() of the committed state is known
  mutable double approach_limit_ = 1e300;
  Event pending_ = Event::kNone;
  int impacts_ = 0;
  int impacts_above_1mm_s_ = 0;
  double max_impact_velocity_ = 0.0;
  double friction_dissipated_ = 0.0;
  double time_stick_ = 0.0, time_slip_ = 0.0;
  EpisodeWork episode_work_;

  void end_episode(const State& at_separation);
};

}  // namespace isopound
