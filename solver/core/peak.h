// Peak of a signal over time: max |x|, max x and min x, each with the time it was reached.
// A value raises a peak only when it strictly exceeds it (the first time a maximum occurs wins).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isopound {

struct Peak {
  double value = 0.0;                          // max |x| over time
  double time = 0.0;                           // s, when it occurred
  double positive = 0.0, time_positive = 0.0;  // max(x, 0) over time and when
  double negative = 0.0, time_negative = 0.0;  // min(x, 0) over time (<= 0) and when
};

inline void update_peak(Peak& peak, double value, double t) {
  // Most calls change nothing: peak.value = max(positive, -negative) (all start at 0), so a value
  // within [negative, positive] cannot raise any of the three (NaN falls through as before).
  if (value <= peak.positive && value >= peak.negative) return;
  const double a = std::abs(value);
  if (a > peak.value) {
    peak.value = a;
    peak.time = t;
  }
  if (value > peak.positive) {
    peak.positive = value;
    peak.time_positive = t;
  }
  if (value < peak.negative) {
    peak.negative = value;
    peak.time_negative = t;
  }
}

// Peaks of many signals recorded together: a flat copy of each peak's band [negative, positive]
// lets one branch-free pass find that no value leaves its band (the common case), without
// touching the Peak records. The peaks are exactly those of update_peak on every value.
class PeakBands {
 public:
  // peaks[k] records values[k]; the Peaks must outlive this object.
  explicit PeakBands(std::vector<Peak*> peaks)
      : peaks_(std::move(peaks)), low_(peaks_.size()), high_(peaks_.size()) {
    for (std::size_t k = 0; k < peaks_.size(); ++k) {
      low_[k] = peaks_[k]->negative;
      high_[k] = peaks_[k]->positive;
    }
  }

  void record(const double* values, double t) {
    const std::size_t n = peaks_.size();
    // NaN counts as outside (update_peak then leaves the peak alone). GCC does not vectorise
    // this test by itself; with SSE2 (every x86-64) two values at a time.
    int outside = 0;
    std::size_t k = 0;
#if defined(__SSE2__)
    for (; k + 2 <= n; k += 2) {
      const __m128d v = _mm_loadu_pd(values + k);
      outside |= _mm_movemask_pd(_mm_or_pd(_mm_cmpnle_pd(v, _mm_loadu_pd(high_.data() + k)),
                                           _mm_cmpnge_pd(v, _mm_loadu_pd(low_.data() + k))));
    }
#endif
    for (; k < n; ++k) outside |= int{!(values[k] <= high_[k])} | int{!(values[k] >= low_[k])};
    if (outside == 0) return;
    for (std::size_t k = 0; k < n; ++k) {
      update_peak(*peaks_[k], values[k], t);
      low_[k] = peaks_[k]->negative;
      high_[k] = peaks_[k]->positive;
    }
  }

 private:
  std::vector<Peak*> peaks_;
  std::vector<double> low_, high_;
};

}  // namespace isopound
