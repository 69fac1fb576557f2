// Summary statistics (see study_statistics.h): two-pass mean and variance (the second pass sums
// squared deviations from the mean, which keeps the variance accurate for large means).
#include "solver/study/study_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isopound {

SummaryStatistics summarize(const std::vector<double>& values, bool sample_std) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> x;
  x.reserve(values.size());
  for (const double v : values)
    if (!std::isnan(v)) x.push_back(v);
  SummaryStatistics s;
  s.n = static_cast<int>(x.size());
  if (x.empty()) {
    s.mean = s.std = s.min = s.max = s.median = kNaN;
    return s;
  }
  double sum = 0.0;
  for (const double v : x) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  double squares = 0.0;
  for (const double v : x) squares += (v - s.mean) * (v - s.mean);
  const int dof = sample_std ? s.n - 1 : s.n;
  s.std = dof > 0 ? std::sqrt(squares / static_cast<double>(dof)) : kNaN;
  std::sort(x.begin(), x.end());
  s.min = x.front();
  s.max = x.back();
  const std::size_t mid = x.size() / 2;
  s.median = x.size() % 2 == 1 ? x[mid] : 0.5 * (x[mid - 1] + x[mid]);
  return s;
}

}  // namespace isopound
