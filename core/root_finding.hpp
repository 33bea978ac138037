#pragma once
// A bracketed root finder for a continuous function with a sign change: the
// Illinois variant of regula falsi. It keeps the bracket, so it cannot leave the
// edge, and converges superlinearly where secant steps alone would stall.
#include <cmath>
#include <optional>

namespace amls {

struct RootResult {
  bool ok = false;   // false if g was undefined somewhere on the way
  double t = 0.0;    // the root's parameter
  int evaluations = 0;
};

// g(t) returns std::optional<double> (nullopt where undefined). Requires
// g(a) = ga and g(b) = gb of opposite signs (a zero counts as positive, as in
// the resampler); stops when the bracket is narrower than `tolerance` or |g|
// falls to `value_tolerance`. Returns the bracket end where |g| is smallest.
template <typename G>
RootResult find_root_illinois(G&& g, double a, double b, double ga, double gb, double tolerance,
                              double value_tolerance = 0.0, int max_evaluations = 100) {
  RootResult r;
  if (ga == 0.0) return {true, a, 0};
  if (gb == 0.0) return {true, b, 0};
  int side = 0;  // which end stayed put last time: -1 a, +1 b
  while (std::abs(b - a) > tolerance && r.evaluations < max_evaluations) {
    double t = (a * gb - b * ga) / (gb - ga);
    if (!(t > a && t < b)) t = 0.5 * (a + b);  // rounding pushed the secant to an end
    const std::optional<double> gt = g(t);
    ++r.evaluations;
    if (!gt) return r;
    if (std::abs(*gt) <= value_tolerance || *gt == 0.0) return {true, t, r.evaluations};
    if ((*gt > 0.0) == (gb > 0.0)) {
      b = t;
      gb = *gt;
      if (side == +1) ga *= 0.5;
      side = +1;
    } else {
      a = t;
      ga = *gt;
      if (side == -1) gb *= 0.5;
      side = -1;
    }
  }
  r.ok = true;
  r.t = std::abs(ga) < std::abs(gb) ? a : b;
  return r;
}

}  // namespace amls
