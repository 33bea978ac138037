#pragma once
// sin(pi x) and cos(pi x) together, for the velocity fields, whose RK4 stages
// spend most of the deform phase in libm's sincos. Reducing pi x by
// multiples of pi / 2 is exact here (x - k / 2 is representable), so the only
// rounding before the series is the product pi f, as in sincos(pi * x).
#include <cmath>
#include <cstdint>
#include <numbers>

namespace amls {

struct SinCos {
  double sin;
  double cos;
};

inline SinCos sin_cos_pi(double x) {
  constexpr double kPi = std::numbers::pi;
  // Beyond this the reduction's integer would overflow (and NaN has none): libm copes.
  if (!(std::abs(x) < 1e15)) return {std::sin(kPi * x), std::cos(kPi * x)};
  // x = k / 2 + f with k the integer nearest to 2x and |f| <= 1/4.
  const auto k = static_cast<std::int64_t>(2.0 * x + (x < 0.0 ? -0.5 : 0.5));
  const double r = kPi * (x - 0.5 * static_cast<double>(k));
  const double r2 = r * r;
  // Taylor series to r^17 and r^18: for |r| <= pi / 4 the first omitted terms
  // are below 1e-19, far under an ulp. Coefficients are 1 / n!, alternating.
  const double sin_r =
      r * (1.0 + r2 * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362880.0 +
      r2 * (-1.0 / 39916800.0 + r2 * (1.0 / 6227020800.0 + r2 * (-1.0 / 1307674368000.0 +
      r2 * (1.0 / 355687428096000.0)))))))));
  const double cos_r =
      1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40320.0 + r2 * (-1.0 / 3628800.0 +
      r2 * (1.0 / 479001600.0 + r2 * (-1.0 / 87178291200.0 + r2 * (1.0 / 20922789888000.0 +
      r2 * (-1.0 / 6402373705728000.0)))))))));
  // pi x = k pi / 2 + r: rotate by the quadrant k mod 4.
  switch (k & 3) {
    case 0: return {sin_r, cos_r};
    case 1: return {cos_r, -sin_r};
    case 2: return {-sin_r, -cos_r};
    default: return {-cos_r, sin_r};
  }
}

}  // namespace amls
