// Summary statistics of a sample (over records, typically): n, mean, standard deviation, mean -/+
// sigma, min, max, median. Sums run in the given order, so equal inputs give equal bits.
#pragma once

#include <vector>

namespace isopound {

struct SummaryStatistics {
  int n = 0;  // values used (NaN values are skipped)
  double mean = 0.0;
  double std = 0.0;  // sample (n - 1) or population (n); NaN for a sample of one
  double min = 0.0;
  double max = 0.0;
  double median = 0.0;  // the middle value, or the mean of the two middle ones
};

// All fields NaN when no value is finite-or-infinite (n = 0).
SummaryStatistics summarize(const std::vector<double>& values, bool sample_std);

}  // namespace isopound
