#pragma once
// The localization function of the paper, eq. (3): psi(s) = (1 - s^2)^4 for s < 1.

namespace amls {

// Takes s^2 = |x - p|^2 / Delta^2 so that callers never need a square root.
inline double weight_of_squared_ratio(double s2) {
  if (s2 >= 1.0) return 0.0;
  const double a = 1.0 - s2;
  const double a2 = a * a;
  return a2 * a2;
}

}  // namespace amls
