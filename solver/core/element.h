// Nonlinear restoring-force elements of a model (isolators now, contacts later) as seen by
// the stepper: trial state from (u, v), force, tangent, commit/revert. No 2D/3D knowledge.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace isopound {

class Element {
 public:
  virtual ~Element() = default;

  // Sets the trial state from global displacements u and velocities v (relative to the
  // ground). Must not allocate: it runs inside every Newton iteration.
  virtual void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) = 0;
  // f += this element's restoring force on the DOFs (same sign as a spring: f = k u).
  virtual void add_force(Eigen::VectorXd& f) const = 0;
  // K += df/du + velocity_factor df/dv (Newmark passes velocity_factor = dv/du = 2/h).
  virtual void add_tangent(Eigen::MatrixXd& K, double velocity_factor) const = 0;
  // Appends the DOFs whose force and tangent this element may ever touch and returns true;
  // false (the default): it may touch any DOF. The stepper eliminates the DOFs no element
  // touches once per step size (newmark.h).
  virtual bool add_dofs(std::vector<int>& /*dofs*/) const { return false; }
  // y += (df/du) x with the stiffness tangent (velocity factor 0) at the trial state, without
  // assembling it, when has_stiffness_product(); the stepper's error estimate uses it.
  virtual bool has_stiffness_product() const { return false; }
  virtual void add_stiffness_product(const Eigen::VectorXd& /*x*/, Eigen::VectorXd& /*y*/) const {}
  // Batches (element_batches.h): a run of consecutive elements with the same non-null
  // batch_key() goes to the first one's *_batch() methods, which must give the same results as
  // the single calls on each element in turn, bit for bit (the stepper and the record use them;
  // a batch lets independent law evaluations overlap in the processor and sums stay in registers).
  virtual const void* batch_key() const { return nullptr; }
  virtual void set_trial_batch(Element* const* elements, int count, const Eigen::VectorXd& u,
                               const Eigen::VectorXd& v) {
    for (int i = 0; i < count; ++i) elements[i]->set_trial(u, v);
  }
  virtual void add_force_batch(Element* const* elements, int count, Eigen::VectorXd& f) const {
    for (int i = 0; i < count; ++i) elements[i]->add_force(f);
  }
  virtual void add_tangent_batch(Element* const* elements, int count, Eigen::MatrixXd& K,
                                 double velocity_factor) const {
    for (int i = 0; i < count; ++i) elements[i]->add_tangent(K, velocity_factor);
  }
  virtual void add_stiffness_product_batch(Element* const* elements, int count,
                                           const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    for (int i = 0; i < count; ++i) elements[i]->add_stiffness_product(x, y);
  }
  // outputs() of each, one after the other from out (output_count() values each).
  virtual void outputs_batch(Element* const* elements, int count, double* out) const {
    for (int i = 0; i < count; ++i) {
      elements[i]->outputs(out);
      out += elements[i]->output_count();
    }
  }
  // power += each power(v), stored += each stored_energy(), in order.
  virtual void add_energy_batch(Element* const* elements, int count, const Eigen::VectorXd& v,
                                double& power, double& stored) const {
    for (int i = 0; i < count; ++i) {
      power += elements[i]->power(v);
      stored += elements[i]->stored_energy();
    }
  }
  // False if add_tangent() may add a non-symmetric matrix (coupled bearings, friction): the
  // stepper then factors with LU instead of a symmetric factorisation.
  virtual bool symmetric_tangent() const { return true; }
  // Power of the element force on the DOFs at the trial state, v . f_e (W).
  virtual double power(const Eigen::VectorXd& v) const = 0;
  // Recoverable energy at the trial state (J); work minus this is dissipated.
  virtual double stored_energy() const = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;

  // False when begin_step, event_fraction, settle_event and step_limit keep their defaults
  // below (no events, no step limit, e.g. a bearing): the analysis then skips those calls.
  virtual bool has_events() const { return true; }
  // Event handling (contacts). begin_step() tells the size of the step about to be tried;
  // with freeze_status the element keeps its committed status (open/closed) through the trial:
  // the step is one cut to end at an event, which settle_event() then applies.
  virtual void begin_step(double /*h*/, bool /*freeze_status*/) {}
  // The analysis's last resort at its smallest step, when Newton flips between the two sides of
  // a force that jumps with the placement (the thesis's contact indentation at a triangle <->
  // quadrilateral overlap): through the trials until the next begin_step without it, the element
  // keeps the committed branch of such a law. It switches in a later step, from the other side.
  virtual void hold_branch(bool /*hold*/) {}
  // After a converged trial: the fraction of the step in (0, 1) at which the element's first
  // status change occurs (contact onset, separation, approach/restitution switch), or 1.
  // The element remembers which event it was.
  virtual double event_fraction() { return 1.0; }
  // After the step cut at this element's event was accepted: switch status now. Returns true
  // if the element's force jumped, so that the stepper must restart from equilibrium.
  virtual bool settle_event() { return false; }
  // Largest step this element wants next (s), e.g. a fraction of a contact period.
  virtual double step_limit() const { return 1e300; }

  // Scalar outputs for histories and peaks (e.g. force, deformation, z).
  virtual int output_count() const = 0;
  virtual std::string output_name(int i) const = 0;  // e.g. "force", unit in output_unit
  virtual std::string output_unit(int i) const = 0;
  // How output i varies in time. A count (impacts, bottomings) or a 0/1 state (slipping,
  // in_contact, yielded, shear_failed) changes only where a step ends (events end steps): a
  // history row inside a step holds it at the step's start, where it interpolates the others
  // (6.36 impacts is no number of impacts); summary.json writes a count as an integer.
  enum class OutputKind { kContinuous, kCount, kState };
  virtual OutputKind output_kind(int) const { return OutputKind::kContinuous; }
  virtual double output(int i) const = 0;
  // All outputs at once into out[0 .. output_count()) (the stepper calls this every step).
  virtual void outputs(double* out) const {
    for (int i = 0; i < output_count(); ++i) out[i] = output(i);
  }
  virtual const std::string& label() const = 0;
};

}  // namespace isopound
