// A 2D contact between two bodies on one line: penetration delta = c_a u_a + c_b u_b - gap -
// indentation
// (> 0 in contact); the law's force F >= 0 pushes them apart: f_a = c_a F, f_b = c_b F.
#pragma once

#include <memory>
#include <string>

#include "solver/core/element.h"
#include "solver/materials/impact_law.h"

namespace isopound {

// Impacts whose approach rate at onset (before any law's floor) reaches this are counted by
// Contact1D::counted_impacts(): slower touches are grazing contacts that carry no momentum to
// speak of, and their number depends on the step (m/s; the default min_impact_velocity).
inline constexpr double kCountedImpactVelocity = 1e-3;

// One side of a contact: a DOF and its coefficient (+1 if moving +x closes the gap, -1 if
// moving -x does). dof = -1: the ground (a rigid, immovable wall), which contributes nothing.
struct ContactBody {
  int dof = -1;
  double coefficient = 0.0;
};

// Contact states follow the trial/commit protocol. A contact starts when delta crosses 0
// upwards: the law gets the approach rate at that instant (Hermite interpolation inside the
// step) as v_imp. It ends when delta returns to 0 or, for a law without tension, when its
// force reaches 0: the penetration there stays as a permanent indentation that widens the gap.
class BumperLaw;

class Contact1D final : public Element {
 public:
  Contact1D(std::string label, ContactBody a, ContactBody b, double gap,
            std::unique_ptr<ImpactLaw> law, double effective_mass, double steps_per_contact);

  void begin_step(double h, bool freeze_status) override {
    h_ = h;
    freeze_ = freeze_status;
  }
  bool add_dofs(std::vector<int>& dofs) const override {
    for (const ContactBody& body : {a_, b_})
      if (body.dof >= 0) dofs.push_back(body.dof);
    return true;
  }
  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void add_force(Eigen::VectorXd& f) const override;
  void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const override;
  double power(const Eigen::VectorXd& v) const override;
  double stored_energy() const override;
  void commit() override;
  void revert() override;
  double event_fraction() override;
  bool settle_event() override;
  double step_limit() const override;

  // 6 for every law; a bumper adds 3 at the end: bumper_compression, bottomings,
  // bumper_dissipated_energy.
  int output_count() const override { return bumper_ ? 9 : 6; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override;
  const std::string& label() const override { return label_; }

  const ContactBody& body_a() const { return a_; }
  const ContactBody& body_b() const { return b_; }
  double gap() const { return gap_; }

  // Outputs by name, for tests.
  int impacts() const { return impacts_; }
  // Impacts with an approach rate >= kCountedImpactVelocity at onset.
  int counted_impacts() const { return counted_impacts_; }
  int trial_impacts() const { return impacts_ + (trial_.started ? 1 : 0); }
  double indentation() const { return indentation_; }
  double max_impact_velocity() const { return max_impact_velocity_; }
  double dissipated_energy() const { return work_ - stored_; }
  double max_penetration() const { return max_penetration_; }
  double force() const { return trial_.force; }
  double penetration() const { return trial_.delta; }

  // With a bumper (bumper_law.h; nullptr otherwise): its peak compression (m), the number of
  // times it bottomed out, the first time (s from the start, < 0 if never) and the energy its
  // rubber dissipated (J, the work of its damping part).
  const BumperLaw* bumper() const { return bumper_; }
  double bumper_peak_compression() const { return peak_compression_; }
  int bottomings() const { return bottomings_; }
  double first_bottoming_time() const { return first_bottoming_; }
  double bumper_dissipated_energy() const { return rubber_work_; }

 private:
  // The state of the contact at the end of a (trial or committed) step.
  struct State {
    double delta = -1.0;  // penetration with the current indentation, m (< 0 open)
    double rate = 0.0;    // d delta / dt, m/s
    bool in_contact = false;
    double force = 0.0;      // N, as applied (>= 0 unless the law allows tension)
    double raw_force = 0.0;  // N, the law's force before the no-tension clamp
    double stiffness = 0.0;  // dF/d delta as applied
    double damping = 0.0;    // dF/d rate as applied
    ImpactPhase phase;
    bool started = false;  // this step began a contact
    bool ended = false;    // this step ended a contact
    double onset_fraction = 1.0;
    double onset_rate = 0.0;            // approach rate at delta = 0 of a contact begun this step
    double end_indentation = 0.0;       // penetration left when a no-tension contact ended
    double rubber_damping_force = 0.0;  // N, a bumper's damping part
  };
  double kinematics(const Eigen::VectorXd& x) const;

  std::string label_;
  ContactBody a_, b_;
  double gap_;
  std::unique_ptr<ImpactLaw> law_;
  double m_eff_;
  double steps_per_contact_;
  double h_ = 0.0;
  bool freeze_ = false;
  // kStage: a bumper whose force jumps at the bottoming out crosses it (status-like).
  enum class Event { kNone, kOnset, kSeparation, kNoTension, kPhase, kStage };
  Event pending_ = Event::kNone;  // the event found by the last event_fraction()
  State committed_, trial_;
  double indentation_ = 0.0;     // accumulated permanent indentation (committed), m
  double contact_step_ = 1e300;  // step limit of the current contact from its estimated period
  int steps_in_contact_ = 0;     // accepted steps since the current contact began
  double rate_change_ = 0.0;     // |d rate / dt| over the last accepted step, m/s^2
  // Step of a contact that would begin at approach speed approach_speed_ (cached, see
  // step_limit): the floor of the time-of-impact limit.
  mutable double approach_speed_ = -1.0, approach_step_ = 1e300;
  int impacts_ = 0;
  int counted_impacts_ = 0;
  double max_impact_velocity_ = 0.0;
  double max_penetration_ = 0.0;
  double work_ = 0.0, trial_work_ = 0.0;      // work of the contact force on the bodies, J
  double stored_ = 0.0, trial_stored_ = 0.0;  // recoverable energy of the contact, J
  const BumperLaw* bumper_ = nullptr;         // law_ when it is a bumper
  double time_ = 0.0;                         // committed time, s (sum of the accepted steps)
  double peak_compression_ = 0.0;
  int bottomings_ = 0;
  double first_bottoming_ = -1.0;
  double rubber_work_ = 0.0, trial_rubber_work_ = 0.0;  // J
};

}  // namespace isopound
