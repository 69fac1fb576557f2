// Figure helpers: colours, colour map, ticks (see figure.h).
#include "post/figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace isopound::post {

Rgb series_colour(int index) {
  // Tableau 10 (minus grey): distinguishable in colour and in greyscale print.
  static constexpr Rgb kColours[] = {{31, 119, 180},  {255, 127, 14},  {44, 160, 44},
                                     {214, 39, 40},   {148, 103, 189}, {140, 86, 75},
                                     {227, 119, 194}, {188, 189, 34},  {23, 190, 207}};
  constexpr int n = sizeof kColours / sizeof kColours[0];
  return kColours[((index % n) + n) % n];
}

Rgb colour_map(double s) {
  // Viridis at 9 stops, linear between them.
  static constexpr double kStops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                          {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                          {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if (!(s >= 0.0)) s = 0.0;  // also NaN
  if (s > 1.0) s = 1.0;
  const double x = s * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  const auto mix = [&](int c) {
    return static_cast<unsigned char>(
        std::lround(kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c])));
  };
  return {mix(0), mix(1), mix(2)};
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) return {lo};
  const double raw = (hi - lo) / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = p;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) {
      step = m * p;
      break;
    }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(lo > 0.0) || !(hi > lo)) return ticks;
  const int e0 = static_cast<int>(std::floor(std::log10(lo)));
  const int e1 = static_cast<int>(std::ceil(std::log10(hi)));
  const bool dense = e1 - e0 <= 2;
  for (int e = e0; e <= e1; ++e)
    for (double m : dense ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
      const double t = m * std::pow(10.0, e);
      if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
    }
  return ticks;
}

std::string tick_label(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

}  // namespace isopound::post
