// The two modes of a Rayleigh fit C = a0 M + a1 K must have distinct frequencies: at one
// frequency xi = a0 / (2 omega) + a1 omega / 2 gives one ratio, so the 2 x 2 system for (a0, a1)
// is singular (NaN at t = 0) or, nearly equal, ill-conditioned (huge a0, a1 of opposite sign).
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

namespace isopound {

// Frequencies closer than this (relative) count as equal for a Rayleigh fit.
inline constexpr double kRayleighDistinctFrequency = 0.01;

class RayleighModesError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Throws RayleighModesError when modes mode_a and mode_b (1-based) of `omega` (rad/s,
// ascending) are closer than kRayleighDistinctFrequency, naming both modes and their periods
// and suggesting the next mode whose frequency is distinct from mode_a's. `what` names the
// system ("the fixed-base superstructure of building 'A'").
void require_distinct_modes(const Eigen::VectorXd& omega, int mode_a, int mode_b,
                            const std::string& what);

}  // namespace isopound
