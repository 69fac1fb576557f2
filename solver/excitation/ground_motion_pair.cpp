// Rotation of a record pair into the model's axes; common sampling of the two components.
#include "solver/excitation/ground_motion_pair.h"

#include <algorithm>
#include <cmath>

namespace isopound {

GroundMotion combine_pair(const GroundMotion& L, const GroundMotion& T, double angle) {
  GroundMotion out;
  out.name = L.name + "+" + T.name;
  out.unit_note = L.unit_note;
  if (!T.unit_note.empty()) out.unit_note += (out.unit_note.empty() ? "" : "\n") + T.unit_note;
  const bool same_dt = std::abs(L.dt - T.dt) <= 1e-12 * std::max(L.dt, T.dt);
  out.dt = same_dt ? L.dt : std::min(L.dt, T.dt);
  const double duration = std::max(L.duration(), T.duration());
  const std::size_t n = same_dt ? std::max(L.acceleration.size(), T.acceleration.size())
                                : static_cast<std::size_t>(std::ceil(duration / out.dt - 1e-9)) + 1;
  const auto sample = [&](const GroundMotion& m, std::size_t k) {
    if (same_dt) return k < m.acceleration.size() ? m.acceleration[k] : 0.0;
    return m.at(static_cast<double>(k) * out.dt);
  };
  const double c = std::cos(angle), s = std::sin(angle);
  out.acceleration.resize(n);
  out.acceleration_y.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double aL = sample(L, k), aT = sample(T, k);
    out.acceleration[k] = aL * c - aT * s;
    out.acceleration_y[k] = aL * s + aT * c;
  }
  return out;
}

}  // namespace isopound
