// Uniaxial restoring-force laws with OpenSees's trial/commit protocol (force as a function of
// deformation and the committed state). Deformation d and force F share one sign convention.
#pragma once

#include <memory>

namespace isopound {

// A rate-independent uniaxial law. set_trial() moves from the last committed state to the
// trial deformation along a monotonic path; commit() accepts it, revert() discards it.
// Implementations allocate nothing in these calls (they run in the stepper's hot loop).
class UniaxialMaterial {
 public:
  virtual ~UniaxialMaterial() = default;

  virtual void set_trial(double deformation) = 0;
  virtual double force() const = 0;     // N, at the trial state
  virtual double tangent() const = 0;   // N/m, consistent dF/dd at the trial state
  virtual double internal() const = 0;  // hysteretic variable z in [-1, 1] (0 if none)
  // Recoverable (elastic) energy at the trial state, J; work done minus this is dissipated.
  virtual double stored_energy() const = 0;
  virtual double deformation() const = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;
  virtual std::unique_ptr<UniaxialMaterial> clone() const = 0;
};

}  // namespace isopound
