#pragma once
// The localization function of the paper, eq. (3): psi(s) = (1 - s^2)^4 for s < 1.

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace amls {

// Takes s^2 = |x - p|^2 / Delta^2 so that callers never need a square root.
// Branch-free (zero from s = 1 on), so that loops over neighbours vectorize.
// GCC compiles std::max in the scalar loops (evaluate_in, update_normals) to a
// branch on s < 1, which neighbour lists put on either side unpredictably;
// maxsd returns what std::max(0.0, x) does for every x (NaN and -0 give +0).
inline double weight_of_squared_ratio(double s2) {
#if defined(__SSE2__)
  const double a = _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(1.0 - s2), _mm_setzero_pd()));
#else
  const double a = std::max(0.0, 1.0 - s2);
#endif
  const double a2 = a * a;
  return a2 * a2;
}

// The weights of N (even) squared ratios at once, as weight_of_squared_ratio()
// gives them bit for bit, two per SSE2 instruction: for the corner loops of
// AmlsSurface::evaluate_cube, where GCC otherwise leaves one scalar maxsd per
// corner between its packed arithmetic.
template <int N>
inline void weights_of_squared_ratios(const double (&s2)[N], double (&w)[N]) {
  static_assert(N % 2 == 0, "pairs");
#if defined(__SSE2__)
  for (int i = 0; i < N; i += 2) {
    __m128d a = _mm_max_pd(_mm_sub_pd(_mm_set1_pd(1.0), _mm_loadu_pd(s2 + i)), _mm_setzero_pd());
    a = _mm_mul_pd(a, a);
    _mm_storeu_pd(w + i, _mm_mul_pd(a, a));
  }
#else
  for (int i = 0; i < N; ++i) w[i] = weight_of_squared_ratio(s2[i]);
#endif
}

}  // namespace amls
