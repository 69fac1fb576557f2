// A yielding storey of a shear building: a uniaxial law of the storey drift d = u_upper - u_lower
// (UniaxialLink) that also books its dissipated energy and whether it has yielded.
// Dissipated energy E_h = W - E_s: W the work of the storey shear along the drift path
// (trapezoidal rule between committed states, W += (F_0 + F_1) (d_1 - d_0) / 2), E_s the law's
// recoverable energy. "Yielded" once |d| >= d_y (the yield drift of the law's backbone).
#pragma once

#include <memory>
#include <string>

#include "solver/elements/uniaxial_link.h"

namespace isopound {

class StoryLink final : public UniaxialLink {
 public:
  // lower may be kGround; yield_drift d_y > 0, m.
  StoryLink(std::string label, int lower, int upper, std::unique_ptr<UniaxialMaterial> law,
            double yield_drift);

  void set_trial(const Eigen::VectorXd& u, const Eigen::VectorXd& v) override;
  void commit() override;
  void revert() override;

  // force [N], drift [m], z [-], hysteretic_energy [J], yielded [0/1]: the peak of `yielded`
  // is reached (first) at the time of first yield.
  int output_count() const override { return 5; }
  std::string output_name(int i) const override;
  std::string output_unit(int i) const override;
  OutputKind output_kind(int i) const override;
  double output(int i) const override;
  void outputs(double* out) const override {
    UniaxialLink::outputs(out);
    out[3] = hysteretic_energy();
    out[4] = yielded_ ? 1.0 : 0.0;
  }

  double yield_drift() const { return yield_drift_; }
  double hysteretic_energy() const { return work_ - law().stored_energy(); }

 private:
  double yield_drift_;
  double work_ = 0.0, work_commit_ = 0.0;
  double force_commit_ = 0.0, drift_commit_ = 0.0;
  bool yielded_ = false, yielded_commit_ = false;
};

}  // namespace isopound
