// The time left of a long run, for its progress line: at the pace of the last ~10 s of wall time
// (kSamples samples, one per line every 0.5 s), not the average since the start, so that a run
// whose steps shrink (contacts, struck columns) is not promised far too soon.
#pragma once

#include <array>
#include <string>

namespace isopound {

class ProgressEstimate {
 public:
  // One sample: `wall_s` seconds since the run started, the analysis at time t of total (s).
  // Returns "about N s left", or "no progress for N s" when t has not moved over the window.
  std::string sample(double wall_s, double t, double total);

 private:
  static constexpr int kSamples = 20;
  struct Sample {
    double wall_s = 0.0;
    double t = 0.0;
  };
  std::array<Sample, kSamples> samples_{};  // a ring; slot 0 starts as the run's start
  int count_ = 1;
};

}  // namespace isopound
