// Biaxial bilinear bearing: elastic predictor F_h* = F_h + k_h dd, radial return to the circle
// |F_h| = (1-alpha) F_y; consistent tangent alpha K_el I + k_h (f_y/|F_h*|) (I - n n^T).
#include "solver/materials/bilinear_biaxial.h"

#include <stdexcept>

namespace isopound {

BilinearBiaxialMaterial::BilinearBiaxialMaterial(double elastic_stiffness, double alpha,
                                                 double yield_force)
    : alpha_k_(alpha * elastic_stiffness),
      k_h_((1.0 - alpha) * elastic_stiffness),
      fh_yield_((1.0 - alpha) * yield_force),
      tangent_(elastic_stiffness * Eigen::Matrix2d::Identity()) {
  if (!(elastic_stiffness > 0) || !(yield_force > 0) || !(alpha >= 0 && alpha < 1))
    throw std::invalid_argument("biaxial bilinear: need K_el > 0, F_y > 0 and 0 <= alpha < 1");
}

void BilinearBiaxialMaterial::set_trial(const Eigen::Vector2d& d, const Eigen::Vector2d&) {
  d_ = d;
  const Eigen::Vector2d fh_trial = fh_commit_ + k_h_ * (d - d_commit_);
  const double norm = fh_trial.norm();
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  if (norm > fh_yield_) {
    const Eigen::Vector2d n = fh_trial / norm;
    fh_ = fh_yield_ * n;
    tangent_ = alpha_k_ * I + (k_h_ * fh_yield_ / norm) * (I - n * n.transpose());
  } else {
    fh_ = fh_trial;
    tangent_ = (alpha_k_ + k_h_) * I;
  }
}

double BilinearBiaxialMaterial::stored_energy() const {
  return 0.5 * alpha_k_ * d_.squaredNorm() + 0.5 * fh_.squaredNorm() / k_h_;
}

void BilinearBiaxialMaterial::commit() {
  d_commit_ = d_;
  fh_commit_ = fh_;
}

void BilinearBiaxialMaterial::revert() {
  d_ = d_commit_;
  fh_ = fh_commit_;
  // The tangent of a zero increment from the committed state (on the surface: radial return).
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const double norm = fh_.norm();
  if (norm < fh_yield_) {
    tangent_ = (alpha_k_ + k_h_) * I;
  } else {
    const Eigen::Vector2d n = fh_ / norm;
    tangent_ = alpha_k_ * I + k_h_ * (I - n * n.transpose());
  }
}

}  // namespace isopound
