#pragma once
// A bracketed root finder for a smooth function with a sign change. It keeps
// the bracket, so it cannot leave the segment, and takes the cheapest step that
// converges fast near a simple root:
//  - the first step goes to a caller's guess if it has one (the walk's Hermite
//    interpolant of the edge's end values and slopes), else Newton's step when
//    the sample carries a slope estimate;
//  - later steps take the secant through the last two samples (order 1.6);
//  - a step that would leave the bracket takes regula falsi on the bracket
//    instead, and after kFastSteps evaluations every other step bisects, so
//    that a function the secant handles badly still converges;
//  - a sign change that is a jump, not a zero (F with the orientation filter
//    jumps where the nearest point switches between two sheets), is noticed
//    when both bracket values stay far above what the function's mean slope
//    over the initial bracket allows on the shrunken bracket, and the search
//    stops there instead of bisecting down to the tolerance.
// Measured on the 512^2 vortex with the resampler's tolerances
// (core/resample/segment_root.hpp): 1.06 evaluations per located grid-edge crossing,
// where Illinois regula falsi from the linear interpolant's zero took 4.1.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace amls {

// What the function gives at a parameter: its value and, if known, an estimate
// of its derivative there (NaN when unknown).
struct RootSample {
  double value = 0.0;
  double slope = std::numeric_limits<double>::quiet_NaN();
};

struct RootOptions {
  double tolerance = 1e-12;        // stop when the bracket is this narrow
  double value_tolerance = 0.0;    // or when |g| falls to this
  // or when the next step would move t by less than this (or half the
  // tolerance): that step's end is then the root, taken without evaluating g
  double step_tolerance = 0.0;
  double first_guess = std::numeric_limits<double>::quiet_NaN();  // used if inside the bracket
  int max_evaluations = 100;
};

struct RootResult {
  bool ok = false;   // false if g was undefined somewhere on the way
  double t = 0.0;    // the root's parameter
  int evaluations = 0;
  bool jump = false;  // the sign change is a discontinuity; t is its nearer side
};

// g(t) returns std::optional<RootSample> (nullopt where undefined). Requires
// g(a) = ga and g(b) = gb of opposite signs (a zero counts as positive, as in
// the resampler). On running out of evaluations or bracket, returns the
// bracket end where |g| is smallest. Stops when a step would move the
// parameter by less than the step tolerance (returning the step's end), the
// bracket is narrower than the tolerance or |g| falls to the value tolerance.
// Smooth functions on the walk's edges need 1 to 4 evaluations; beyond this
// many the function is not behaving like one.
inline constexpr int kFastSteps = 8;
// A smooth function's values on a bracket of width w stay within a few times
// its mean slope times w; both ends above this many times that mean a jump.
inline constexpr double kJumpFactor = 100.0;

template <typename G>
RootResult find_root(G&& g, double a, double b, double ga, double gb, const RootOptions& options) {
  RootResult r;
  if (ga == 0.0) return {true, a, 0};
  if (gb == 0.0) return {true, b, 0};
  const double mean_slope = (std::abs(ga) + std::abs(gb)) / std::abs(b - a);
  double t = options.first_guess;
  double previous_t = 0.0;
  double previous_g = 0.0;
  bool have_previous = false;
  while (std::abs(b - a) > options.tolerance && r.evaluations < options.max_evaluations) {
    if (r.evaluations >= kFastSteps) {
      if (std::min(std::abs(ga), std::abs(gb)) > kJumpFactor * mean_slope * std::abs(b - a)) {
        r.ok = r.jump = true;
        r.t = std::abs(ga) < std::abs(gb) ? a : b;
        return r;
      }
      if (r.evaluations % 2 == 0) t = 0.5 * (a + b);
    }
    if (!(t > std::min(a, b) && t < std::max(a, b))) t = (a * gb - b * ga) / (gb - ga);
    if (!(t > std::min(a, b) && t < std::max(a, b))) t = 0.5 * (a + b);  // rounding pushed it to an end
    const std::optional<RootSample> sample = g(t);
    ++r.evaluations;
    if (!sample) return r;
    const double gt = sample->value;
    if (std::abs(gt) <= options.value_tolerance || gt == 0.0) return {true, t, r.evaluations};
    if ((gt > 0.0) == (gb > 0.0)) {
      b = t;
      gb = gt;
    } else {
      a = t;
      ga = gt;
    }
    double next = std::numeric_limits<double>::quiet_NaN();
    if (have_previous && gt != previous_g) {
      next = t - gt * (t - previous_t) / (gt - previous_g);
    } else if (std::isfinite(sample->slope) && sample->slope != 0.0) {
      next = t - gt / sample->slope;
    }
    // A step this short means t is already that close to the root, and the
    // step's end (Newton's or the secant's, from that close) closer still.
    if (std::abs(next - t) <= std::max(0.5 * options.tolerance, options.step_tolerance)) {
      const bool inside = next > std::min(a, b) && next < std::max(a, b);
      return {true, inside ? next : t, r.evaluations};
    }
    // Secant steps shrink superlinearly near a simple root: the error left
    // after a step is about step^2 / previous step. When that is below the
    // tolerance, the step's end is the root and needs no evaluation.
    if (have_previous && next > std::min(a, b) && next < std::max(a, b) &&
        (next - t) * (next - t) <= options.tolerance * std::abs(t - previous_t))
      return {true, next, r.evaluations};
    previous_t = t;
    previous_g = gt;
    have_previous = true;
    t = next;
  }
  r.ok = true;
  r.t = std::abs(ga) < std::abs(gb) ? a : b;
  return r;
}

}  // namespace amls
