// 2D contact element: contact status with trial/commit, onset velocity and event fractions by
// cubic Hermite interpolation of the penetration over the step, no-tension clamp with indentation.
#include "solver/elements/contact.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/elements/contact_step.h"
#include "solver/elements/witness.h"
#include "solver/materials/bumper_law.h"

namespace isopound {

namespace {
constexpr double kIgnoredEventFraction = 1e-4;  // events this close to the step start are "at" it
}  // namespace

Contact1D::Contact1D(std::string label, ContactBody a, ContactBody b, double gap,
                     std::unique_ptr<ImpactLaw> law, double effective_mass,
                     double steps_per_contact)
    : label_(std::move(label)),
      a_(a),
      b_(b),
      gap_(gap),
      law_(std::move(law)),
      m_eff_(effective_mass),
      steps_per_contact_(steps_per_contact) {
  committed_.delta = -gap;
  trial_ = committed_;
  bumper_ = dynamic_cast<const BumperLaw*>(law_.get());
}

double Contact1D::kinematics(const Eigen::VectorXd& x) const {
  double s = 0.0;
  if (a_.dof >= 0) s += a_.coefficient * x[a_.dof];
  if (b_.dof >= 0) s += b_.coefficient * x[b_.dof];
  return s;
}

void Contact1D::set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  State& T = trial_;
  const State& C = committed_;
  T.delta = kinematics(u) - gap_ - indentation_;
  T.rate = kinematics(v);
  T.in_contact = C.in_contact;
  T.phase = C.phase;
  T.started = T.ended = false;
  T.onset_fraction = 1.0;
  T.end_indentation = 0.0;
  T.rubber_damping_force = 0.0;

  if (freeze_) {
    // A step cut to end at an event: the status changes only in settle_event().
  } else if (!C.in_contact && T.delta > 0 &&
             !(C.delta > 0 && C.rate <= 0 && T.rate <= 0 && T.delta <= C.delta)) {
    // Onset inside this step: the approach rate at delta = 0 is the impact velocity. A step
    // that began already past 0 (open but penetrating, after a cut) starts it at once, unless
    // the bodies separate throughout it: a separation cut where the step's state still
    // overlaps by a hair (the event is located on the interpolant; a massless node's position
    // is not) is no new impact (a Kelvin-Voigt contact opening under tension counted one).
    const WitnessStep w{C.delta, C.rate, T.delta, T.rate, h_};
    double theta = first_status_change(w, false, 0.0);
    if (theta >= 1.0) theta = 0.0;
    const double rate_at_onset = theta > 0 ? witness_rate(w, theta) : C.rate;
    T.onset_rate = rate_at_onset;
    law_->begin_contact(std::max(rate_at_onset, 0.0), T.phase);
    T.in_contact = true;
    T.started = true;
    T.onset_fraction = theta;
  } else if (C.in_contact && T.delta <= 0) {
    T.in_contact = false;
    T.ended = true;
  }
  if (!freeze_ && bumper_ && bumper_->bottoming_jumps())
    T.phase.bottomed = T.in_contact && T.delta > bumper_->stage_penetration();

  T.force = T.raw_force = T.stiffness = T.damping = 0.0;
  double stored = 0.0;
  if (T.in_contact) {
    // A frozen contact may end its step a hair outside (delta = -1e-15): take the limit at 0.
    const ImpactResponse r = law_->respond(std::max(T.delta, 0.0), T.rate, T.phase);
    T.raw_force = r.force;
    if (r.force < 0 && !law_->tension_allowed() && freeze_) {
      T.force = T.stiffness = T.damping = 0.0;  // clamped; the contact ends at settle_event()
    } else if (r.force < 0 && !law_->tension_allowed()) {
      // No tension: the contact ends here, leaving the penetration as permanent indentation.
      T.in_contact = false;
      T.ended = true;
      T.end_indentation = T.delta;
    } else {
      T.force = r.force;
      T.stiffness = r.stiffness;
      T.damping = r.damping;
      stored = law_->stored_energy(T.delta, T.phase);  // of the elastic part F(delta, 0)
      if (bumper_ && T.force > 0)
        T.rubber_damping_force = bumper_->rubber_damping_force(T.delta, T.rate, T.phase);
    }
  }
  trial_stored_ = stored;
  trial_work_ = work_ + 0.5 * h_ * (C.force * C.rate + T.force * T.rate);
  if (bumper_)
    trial_rubber_work_ =
        rubber_work_ +
        0.5 * h_ * (C.rubber_damping_force * C.rate + T.rubber_damping_force * T.rate);
}

void Contact1D::add_force(Eigen::VectorXd& f) const {
  if (trial_.force == 0.0) return;
  if (a_.dof >= 0) f[a_.dof] += a_.coefficient * trial_.force;
  if (b_.dof >= 0) f[b_.dof] += b_.coefficient * trial_.force;
}

void Contact1D::add_tangent(Eigen::MatrixXd& K, double velocity_factor) const {
  const double k = trial_.stiffness + velocity_factor * trial_.damping;
  if (k == 0.0) return;
  const ContactBody bodies[2] = {a_, b_};
  for (const ContactBody& p : bodies) {
    if (p.dof < 0) continue;
    for (const ContactBody& q : bodies)
      if (q.dof >= 0) K(p.dof, q.dof) += p.coefficient * q.coefficient * k;
  }
}

double Contact1D::power(const Eigen::VectorXd& v) const {
  return trial_.force * kinematics(v);
}

double Contact1D::stored_energy() const {
  return trial_stored_;
}

void Contact1D::commit() {
  if (trial_.started) {
    contact_step_ = contact_period_estimate(*law_, trial_.phase, m_eff_) / steps_per_contact_;
    ++impacts_;
    if (trial_.onset_rate >= kCountedImpactVelocity) ++counted_impacts_;
    max_impact_velocity_ = std::max(max_impact_velocity_, trial_.phase.impact_velocity);
  }
  if (trial_.in_contact) max_penetration_ = std::max(max_penetration_, trial_.delta);
  if (trial_.ended && trial_.end_indentation > 0) {
    indentation_ += trial_.end_indentation;
    trial_.delta -= trial_.end_indentation;
  }
  if (h_ > 0) rate_change_ = std::abs(trial_.rate - committed_.rate) / h_;
  work_ = trial_work_;
  stored_ = trial_stored_;
  if (bumper_) {
    time_ += h_;
    rubber_work_ = trial_rubber_work_;
    if (trial_.in_contact) {
      peak_compression_ = std::max(peak_compression_, bumper_->compression(trial_.delta));
      const double s = bumper_->stage_penetration();
      if (committed_.delta <= s && trial_.delta > s) {  // bottomed out in this step
        ++bottomings_;
        if (first_bottoming_ < 0) first_bottoming_ = time_;
      }
    }
  }
  committed_ = trial_;
  steps_in_contact_ = trial_.started ? 0 : steps_in_contact_ + 1;
}

void Contact1D::revert() {
  trial_ = committed_;
  trial_stored_ = stored_;
  trial_work_ = work_;
  trial_rubber_work_ = rubber_work_;
}

double Contact1D::event_fraction() {
  const State& C = committed_;
  const State& T = trial_;
  double theta = 1.0;
  pending_ = Event::kNone;
  // Status changes are reported wherever they fall in [0, 1) (the driver settles one at the
  // step start at once, one at the end after a frozen redo); the approach/restitution switch,
  // where the force is continuous, only when it is inside the step.
  const auto consider = [&](double f, Event kind) {
    const bool inside = f > kIgnoredEventFraction && f < 1.0 - kIgnoredEventFraction;
    if ((kind != Event::kPhase || inside) && f < theta) {
      theta = std::max(f, 0.0);
      pending_ = kind;
    }
  };
  const WitnessStep w{C.delta, C.rate, T.delta, T.rate, h_};
  if (T.started) consider(std::min(T.onset_fraction, 1.0 - 1e-15), Event::kOnset);
  if (C.in_contact && T.ended) {
    const double f = T.end_indentation > 0  // no-tension law: its force reached 0
                         ? C.raw_force / (C.raw_force - T.raw_force)
                         : first_status_change(w, true, 0.0);
    consider(std::min(f, 1.0 - 1e-15),
             T.end_indentation > 0 ? Event::kNoTension : Event::kSeparation);
  }
  // Crossings that the step's ends do not show: the interpolant rises above 0 inside an open
  // step and falls back (a missed onset), or dips below 0 inside a closed one (a missed
  // separation, the grazing end of a long contact).
  if (!C.in_contact && !T.started) {
    const double f = first_status_change(w, false);
    if (f < 1.0) consider(f, Event::kOnset);
  }
  if (C.in_contact && T.in_contact) {
    const double f = first_status_change(w, true);
    if (f < 1.0) consider(f, Event::kSeparation);
  }
  if (C.in_contact && T.in_contact && C.rate > 0 && T.rate <= 0)  // approach -> restitution
    consider(C.rate / (C.rate - T.rate), Event::kPhase);
  // A bumper bottoming out (or coming back): the force is continuous but its slope jumps by
  // the wall's stiffness, so the step ends there too. Where the force jumps (kJump) it is a
  // status change, settled like an onset.
  if (const double s = law_->stage_penetration(); s < 1e300 && C.in_contact && T.in_contact) {
    const bool jumps = bumper_ && bumper_->bottoming_jumps();
    const WitnessStep ws{C.delta - s, C.rate, T.delta - s, T.rate, h_};
    double f = first_status_change(ws, jumps ? C.phase.bottomed : C.delta > s);
    if (jumps && T.phase.bottomed != C.phase.bottomed) f = std::min(f, 1.0 - 1e-15);
    if (f < 1.0) consider(f, jumps ? Event::kStage : Event::kPhase);
  }
  return theta;
}

bool Contact1D::settle_event() {
  State& C = committed_;
  const Event event = pending_;
  pending_ = Event::kNone;
  switch (event) {
    case Event::kOnset:
      if (C.in_contact) return false;
      law_->begin_contact(std::max(C.rate, 0.0), C.phase);
      contact_step_ = contact_period_estimate(*law_, C.phase, m_eff_) / steps_per_contact_;
      steps_in_contact_ = 0;
      C.in_contact = true;
      ++impacts_;
      if (C.rate >= kCountedImpactVelocity) ++counted_impacts_;
      max_impact_velocity_ = std::max(max_impact_velocity_, C.phase.impact_velocity);
      break;
    case Event::kSeparation:
      if (!C.in_contact) return false;
      C.in_contact = false;
      break;
    case Event::kNoTension: {
      if (!C.in_contact) return false;
      const double left = std::max(C.delta, 0.0);
      indentation_ += left;
      C.delta -= left;
      C.in_contact = false;
      break;
    }
    case Event::kStage:
      if (!C.in_contact) return false;
      C.phase.bottomed = !C.phase.bottomed;
      break;
    case Event::kPhase:
    case Event::kNone:
      return false;  // the force is continuous there
  }
  trial_ = C;
  return true;
}

// Pseudocode. Open: conservative advancement (time of impact, contact_step.h) with |delta''|
// <= A, taken as twice the mean |delta''| of the last step (an estimate, not a proof: the
// interior-crossing test of event_fraction() is the backstop); the step is at most that time,
// but never below the step of a contact that would begin at the arrival speed (else the steps
// would shrink to 0 along a grazing approach). Closed: a fraction of the contact period, graded
// from the onset.
double Contact1D::step_limit() const {
  const State& C = committed_;
  if (!C.in_contact) {
    const TimeOfImpact toi = time_of_impact(-C.delta, C.rate, 2.0 * rate_change_);
    if (toi.time >= 1e300) return 1e300;
    // The floor changes slowly with the speed (not at all for the linear-type laws, as
    // v^(-1/5) for Hertz): recomputed only when it may bind and the speed moved by 25 %.
    if (toi.time >= 2.0 * approach_step_) return toi.time;
    const double speed = std::max(toi.arrival_speed, kCountedImpactVelocity);
    if (!(std::abs(speed - approach_speed_) <= 0.25 * approach_speed_)) {
      ImpactPhase phase;
      law_->begin_contact(speed, phase);
      approach_step_ = contact_period_estimate(*law_, phase, m_eff_) / steps_per_contact_;
      approach_speed_ = speed;
    }
    return std::max(toi.time, approach_step_);
  }
  double limit = graded_contact_step(contact_step_, steps_in_contact_);
  if (C.stiffness > 0)
    limit =
        std::min(limit, std::numbers::pi * std::sqrt(m_eff_ / C.stiffness) / steps_per_contact_);
  return limit;
}

std::string Contact1D::output_name(int i) const {
  static const char* kNames[] = {"force",
                                 "penetration",
                                 "impacts",
                                 "impact_velocity",
                                 "indentation",
                                 "dissipated_energy",
                                 "bumper_compression",
                                 "bottomings",
                                 "bumper_dissipated_energy"};
  return kNames[i];
}

std::string Contact1D::output_unit(int i) const {
  static const char* kUnits[] = {"N", "m", "-", "m/s", "m", "J", "m", "-", "J"};
  return kUnits[i];
}

Element::OutputKind Contact1D::output_kind(int i) const {
  return i == 2 || i == 7 ? OutputKind::kCount : OutputKind::kContinuous;  // impacts, bottomings
}

void Contact1D::outputs(double* out) const {
  out[0] = trial_.force;
  out[1] = std::max(trial_.delta, 0.0);
  out[2] = trial_impacts();
  out[3] = std::max(max_impact_velocity_, trial_.started ? trial_.phase.impact_velocity : 0.0);
  out[4] = indentation_ + (trial_.ended ? trial_.end_indentation : 0.0);
  out[5] = trial_work_ - trial_stored_;
  if (!bumper_) return;
  out[6] = trial_.in_contact ? bumper_->compression(trial_.delta) : 0.0;
  const double s = bumper_->stage_penetration();
  out[7] = bottomings_ + (trial_.in_contact && committed_.delta <= s && trial_.delta > s ? 1 : 0);
  out[8] = trial_rubber_work_;
}

double Contact1D::output(int i) const {
  double values[9];
  outputs(values);
  return values[i];
}

}  // namespace isopound
