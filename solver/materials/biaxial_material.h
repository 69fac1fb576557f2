// Biaxial restoring-force laws of one bearing in plan (x, y), with OpenSees's trial/commit
// protocol. Deformation d = (d_x, d_y) and force F share one sign convention (F = K d).
#pragma once

#include <Eigen/Dense>
#include <memory>

namespace isopound {

// A bearing law in plan: coupled or uncoupled Bouc-Wen, biaxial bilinear, linear, friction
// pendulum. set_trial() moves from the last committed state to the trial deformation along a
// straight path (and, for rate-dependent laws such as friction, with the trial rate);
// commit() accepts it, revert() discards it. Nothing allocates in these calls (hot loop).
class BiaxialMaterial {
 public:
  virtual ~BiaxialMaterial() = default;

  // d: trial deformation (m); rate: its time derivative at the trial state (m/s).
  virtual void set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d& rate) = 0;
  virtual Eigen::Vector2d force() const = 0;  // N, at the trial state
  // Consistent dF/dd at the trial state (N/m); non-symmetric for coupled laws.
  virtual Eigen::Matrix2d tangent() const = 0;
  // dF/d(rate) at the trial state (N s/m); zero for rate-independent laws.
  virtual Eigen::Matrix2d rate_tangent() const { return Eigen::Matrix2d::Zero(); }
  // True when tangent() and rate_tangent() are always symmetric (the stepper may then use a
  // symmetric factorisation).
  virtual bool symmetric_tangent() const = 0;
  virtual Eigen::Vector2d internal() const = 0;  // hysteretic variables (z_x, z_y), 0 if none
  // Recoverable (elastic) energy at the trial state, J; work done minus this is dissipated.
  virtual double stored_energy() const = 0;
  virtual Eigen::Vector2d deformation() const = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;
  virtual std::unique_ptr<BiaxialMaterial> clone() const = 0;
};

}  // namespace isopound
