#include "solver/io/progress_estimate.h"

#include <cstdio>

namespace isopound {

std::string ProgressEstimate::sample(double wall_s, double t, double total) {
  // The oldest sample of the window, copied before its slot takes the new one (the slot is the
  // same once the ring is full).
  const Sample from = samples_[count_ < kSamples ? 0 : count_ % kSamples];
  samples_[count_++ % kSamples] = {wall_s, t};
  const double wall = wall_s - from.wall_s;
  const double done = t - from.t;
  char text[64];
  if (done > 0)
    std::snprintf(text, sizeof text, "about %.0f s left", wall * (total - t) / done);
  else
    std::snprintf(text, sizeof text, "no progress for %.0f s", wall);
  return text;
}

}  // namespace isopound
