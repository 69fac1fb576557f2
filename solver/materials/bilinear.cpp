// Sharp bilinear isolator: elastic predictor, return to the yield surface |F_h| = (1-alpha) F_y.
// Exact for a monotonic deformation increment.
#include "solver/materials/bilinear.h"

#include <cmath>
#include <stdexcept>

namespace isopound {

BilinearMaterial::BilinearMaterial(double elastic_stiffness, double alpha, double yield_force)
    : alpha_k_(alpha * elastic_stiffness),
      k_h_((1.0 - alpha) * elastic_stiffness),
      fh_yield_((1.0 - alpha) * yield_force),
      tangent_(elastic_stiffness) {
  if (!(elastic_stiffness > 0) || !(yield_force > 0) || !(alpha >= 0 && alpha < 1))
    throw std::invalid_argument("bilinear: need K_el > 0, F_y > 0 and 0 <= alpha < 1");
}

void BilinearMaterial::set_trial(double d) {
  d_ = d;
  const double fh_trial = fh_commit_ + k_h_ * (d - d_commit_);
  if (std::abs(fh_trial) > fh_yield_) {
    fh_ = std::copysign(fh_yield_, fh_trial);
    tangent_ = alpha_k_;
  } else {
    fh_ = fh_trial;
    tangent_ = alpha_k_ + k_h_;
  }
}

double BilinearMaterial::stored_energy() const {
  return 0.5 * alpha_k_ * d_ * d_ + 0.5 * fh_ * fh_ / k_h_;
}

void BilinearMaterial::commit() {
  d_commit_ = d_;
  fh_commit_ = fh_;
}

void BilinearMaterial::revert() {
  d_ = d_commit_;
  fh_ = fh_commit_;
  tangent_ = std::abs(fh_) < fh_yield_ ? alpha_k_ + k_h_ : alpha_k_;
}

}  // namespace isopound
