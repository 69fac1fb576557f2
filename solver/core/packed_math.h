// Square roots and quotients of many independent values two at a time (SSE2, every x86-64): the
// same correctly rounded results as one at a time, and a packed square root or division costs
// the divider about what a scalar one does, which is what bounds a batch of them (the bearings'
// resultants, the closed forms of their laws).
#pragma once

#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isopound {

// out[i] = sqrt(in[i]), i < n (out may be in).
inline void sqrt_each(const double* in, double* out, int n) {
  int i = 0;
#if defined(__SSE2__)
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(out + i, _mm_sqrt_pd(_mm_loadu_pd(in + i)));
#endif
  for (; i < n; ++i) out[i] = std::sqrt(in[i]);
}

// out[i] = 1 / (q[i] (1 + q[i])), i < n.
inline void inverse_q_one_plus_q(const double* q, double* out, int n) {
  int i = 0;
#if defined(__SSE2__)
  const __m128d one = _mm_set1_pd(1.0);
  for (; i + 2 <= n; i += 2) {
    const __m128d qi = _mm_loadu_pd(q + i);
    _mm_storeu_pd(out + i, _mm_div_pd(one, _mm_mul_pd(qi, _mm_add_pd(one, qi))));
  }
#endif
  for (; i < n; ++i) out[i] = 1.0 / (q[i] * (1.0 + q[i]));
}

}  // namespace isopound
