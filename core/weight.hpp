#pragma once
// The localization function of the paper, eq. (3): psi(s) = (1 - s^2)^4 for s < 1.

#include <algorithm>

namespace amls {

// Takes s^2 = |x - p|^2 / Delta^2 so that callers never need a square root.
// Branch-free (zero from s = 1 on), so that loops over neighbours vectorize.
inline double weight_of_squared_ratio(double s2) {
  const double a = std::max(0.0, 1.0 - s2);
  const double a2 = a * a;
  return a2 * a2;
}

}  // namespace amls
