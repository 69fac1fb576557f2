// Distinct modes for a Rayleigh fit (see rayleigh_modes.h).
#include "solver/structures/rayleigh_modes.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace isopound {
namespace {

bool close(double wa, double wb) {
  return std::abs(wa - wb) < kRayleighDistinctFrequency * std::max(std::abs(wa), std::abs(wb));
}

std::string period_text(double omega) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g s", 2.0 * std::numbers::pi / omega);
  return buffer;
}

}  // namespace

void require_distinct_modes(const Eigen::VectorXd& omega, int mode_a, int mode_b,
                            const std::string& what) {
  const int count = static_cast<int>(omega.size());
  if (mode_a < 1 || mode_b < 1 || mode_a > count || mode_b > count) return;  // checked elsewhere
  const double wa = omega[mode_a - 1], wb = omega[mode_b - 1];
  if (!close(wa, wb)) return;
  std::string message = "Rayleigh damping at modes " + std::to_string(mode_a) + " and " +
                        std::to_string(mode_b) + " of " + what + ": their periods " +
                        period_text(wa) + " and " + period_text(wb) +
                        " are equal (within 1 %), so two ratios cannot be fitted there";
  const int low = std::min(mode_a, mode_b);
  int next = 0;
  for (int k = std::max(mode_a, mode_b) + 1; k <= count && next == 0; ++k)
    if (!close(omega[low - 1], omega[k - 1])) next = k;
  if (next > 0)
    message += "; use the next distinct mode: modes: [" + std::to_string(low) + ", " +
               std::to_string(next) + "] (mode " + std::to_string(next) + ": " +
               period_text(omega[next - 1]) + ")";
  else
    message += "; no later mode has a distinct period: use type: none or one ratio";
  throw RayleighModesError(message);
}

}  // namespace isopound
