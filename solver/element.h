// Nonlinear restoring-force elements of a model (isolators now, contacts later) as seen by
// the stepper: trial state from (u, v), force, tangent, commit/revert. No 2D/3D knowledge.
#pragma once

#include <Eigen/Dense>
#include <string>

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
  // Power of the element force on the DOFs at the trial state, v . f_e (W).
  virtual double power(const Eigen::VectorXd& v) const = 0;
  // Recoverable energy at the trial state (J); work minus this is dissipated.
  virtual double stored_energy() const = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;

  // Scalar outputs for histories and peaks (e.g. force, deformation, z).
  virtual int output_count() const = 0;
  virtual std::string output_name(int i) const = 0;  // e.g. "force", unit in output_unit
  virtual std::string output_unit(int i) const = 0;
  virtual double output(int i) const = 0;
  virtual const std::string& label() const = 0;
};

}  // namespace isopound
