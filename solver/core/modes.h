// Undamped modes of a linear system K phi = omega^2 M phi: periods ascending, mass-normalised
// shapes (phi^T M phi = 1), and participation of the ground-motion influence vector.
#pragma once

#include <Eigen/Dense>

namespace isopound {

struct Modes {
  Eigen::VectorXd omega;                 // rad/s, ascending
  Eigen::VectorXd period;                // s
  Eigen::MatrixXd shape;                 // column j = mode j, phi^T M phi = 1
  Eigen::VectorXd participation;         // Gamma_j = phi_j^T M iota
  Eigen::VectorXd effective_mass_ratio;  // Gamma_j^2 / (iota^T M iota)
};

// Throws std::invalid_argument if M is not positive definite or K is not positive definite.
Modes compute_modes(const Eigen::MatrixXd& stiffness, const Eigen::MatrixXd& mass,
                    const Eigen::VectorXd& influence);

}  // namespace isopound
