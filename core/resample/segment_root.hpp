#pragma once
// The zero of F on a short segment whose ends have opposite signs, located by
// a safeguarded secant iteration (core/math/root_finding.hpp) started from a cubic
// Hermite guess (estimate_segment_root()), to kSegmentRootStep or better, with
// the unit normal a new point gets there: the fitted sphere's gradient at the
// root when the root's own evaluation gave it, else the gradients of the ends
// interpolated. Where F turns undefined inside the segment, the zero of the
// linear interpolant of the end values is taken instead (a fallback). Used by
// the grid walk (on grid edges) and by the ray tracer (between ray samples).
#include <cmath>
#include <limits>

#include "core/surface/gradient_fit.hpp"
#include "core/math/root_finding.hpp"

namespace amls {

// Roots are located to this fraction of the segment: near machine precision
// for coordinates of order one on grids up to a few thousand cells...
inline constexpr double kSegmentRootTolerance = 1e-12;
// ...except where the root finder's next step, Newton's (with the fitted
// gradient's slope) or the secant's, is shorter than this fraction: its end
// is then taken without evaluating F. From the Hermite guess that is mostly
// the first step, so most crossings take one evaluation instead of two. The
// points lie on average 7e-11 and at most 4e-7 of the segment from the roots
// located to 1e-12 on the 512^2 vortex, 4e-10 and 3e-5 on the 128^3 Enright
// test, and their normals within 1.3e-5. Loosening the bracket's or the
// secant's tolerance as far instead breaks that Enright test, where slopes and
// secants are rougher guides.
inline constexpr double kSegmentRootStep = 1e-5;
// An evaluation this close to the root (in units of the segment) gives the new
// point's normal; the fitted gradient changes by about as little over it.
// It must reach beyond kSegmentRootStep: otherwise the end of an unevaluated
// step would get the ends' interpolated normals, which in 3D are rough.
inline constexpr double kNormalReach = 1e-4;
static_assert(kNormalReach > kSegmentRootStep);

template <int D>
struct SegmentRoot {
  double t = 0.0;                    // 0 at the segment's start, 1 at its end
  Vec<D> normal = Vec<D>::Zero();    // unit
  int evaluations = 0;               // of F by the root finder
  bool fallback = false;             // F was undefined on the way: t is the interpolant's zero
  // The sign change is a jump of F, not a zero (core/math/root_finding.hpp):
  // t is the jump's nearer side, and no surface passes there.
  bool jump = false;
};

// The unit normal a new point carries. It only orients the next fit, so its
// orientation must be the neighbours': where the fitted sphere's gradient turns
// against their mean normal (a sharp or badly sampled spot), the mean normal is
// used. `fallback_axis` is the last resort for a zero vector.
template <int D>
Vec<D> oriented_unit_normal(Vec<D> normal, const Vec<D>& orientation, int fallback_axis) {
  if (normal.dot(orientation) <= 0.0) normal = orientation;
  const double length = normal.norm();
  return length > 0.0 ? Vec<D>(normal / length) : Vec<D>::Unit(fallback_axis);
}

// The normal at parameter t of the segment from its ends' fits.
template <int D>
Vec<D> interpolated_normal(const Evaluation<D>& f0, const Evaluation<D>& f1, double t, int fallback_axis) {
  return oriented_unit_normal<D>((1.0 - t) * f0.gradient + t * f1.gradient,
                                 (1.0 - t) * f0.mean_normal + t * f1.mean_normal, fallback_axis);
}

// The zero of the linear interpolant of the end values, as a fraction of the segment.
template <int D>
double linear_segment_root(const Evaluation<D>& f0, const Evaluation<D>& f1) {
  return f0.value / (f0.value - f1.value);
}

// The crossing by linear interpolation of the ends: the interpolated variant's point.
template <int D>
SegmentRoot<D> interpolate_segment_root(const Evaluation<D>& f0, const Evaluation<D>& f1, int fallback_axis) {
  SegmentRoot<D> out;
  out.t = linear_segment_root(f0, f1);
  out.normal = interpolated_normal(f0, f1, out.t, fallback_axis);
  return out;
}

// The zero in (0, 1) of the cubic Hermite interpolant of values v0, v1 and
// slopes s0, s1 at t = 0 and 1, by Newton's method from `t` (the linear
// interpolant's zero); NaN if Newton leaves the segment. The slopes come from
// the fitted spheres' gradients, which near a smooth surface are close to F's
// own, so the guess is typically far closer than the linear one.
inline double hermite_root_guess(double v0, double v1, double s0, double s1, double t) {
  for (int k = 0; k < 8; ++k) {
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double value = (2 * t3 - 3 * t2 + 1) * v0 + (t3 - 2 * t2 + t) * s0 + (3 * t2 - 2 * t3) * v1 + (t3 - t2) * s1;
    const double slope = (6 * t2 - 6 * t) * (v0 - v1) + (3 * t2 - 4 * t + 1) * s0 + (3 * t2 - 2 * t) * s1;
    const double step = value / slope;
    t -= step;
    if (!(t > 0.0 && t < 1.0)) return std::numeric_limits<double>::quiet_NaN();
    if (std::abs(step) <= 1e-12) break;
  }
  return t;
}

// Where the zero of F on the segment from f0 to f1 (`step` long) lies, from
// the ends alone: the zero of the cubic Hermite interpolant of their values
// and fit gradients, or the linear interpolant's where Newton leaves the
// segment. The root finder starts there; the resampler also settles
// HAVECLOSEPOINT on it (core/resample/resampler.hpp).
template <int D>
double estimate_segment_root(const Evaluation<D>& f0, const Evaluation<D>& f1, const Vec<D>& step) {
  const double linear_t = linear_segment_root(f0, f1);
  const double hermite_t = hermite_root_guess(f0.value, f1.value, f0.gradient.dot(step), f1.gradient.dot(step), linear_t);
  return std::isnan(hermite_t) ? linear_t : hermite_t;
}

// `evaluate(y)` returns F's Evaluation<D> at y. f0 and f1 are F at `start` and
// `start + step`, defined and of opposite signs (a zero counts as positive);
// `guess` is estimate_segment_root()'s.
template <int D, typename Evaluate>
SegmentRoot<D> locate_segment_root(Evaluate&& evaluate, const Vec<D>& start, const Vec<D>& step,
                                   const Evaluation<D>& f0, const Evaluation<D>& f1, double guess, int fallback_axis) {
  SegmentRoot<D> out;
  const double linear_t = linear_segment_root(f0, f1);
  // The evaluation with the smallest |F| so far: the root's, at the end.
  double best_t = std::abs(f0.value) <= std::abs(f1.value) ? 0.0 : 1.0;
  Evaluation<D> best = best_t == 0.0 ? f0 : f1;
  RootOptions options;
  options.tolerance = kSegmentRootTolerance;
  options.step_tolerance = kSegmentRootStep;
  options.value_tolerance = kSegmentRootTolerance * (std::abs(f0.value) + std::abs(f1.value));
  options.first_guess = guess;
  const RootResult root = find_root(
      [&](double t) -> std::optional<RootSample> {
        const Evaluation<D> e = evaluate(Vec<D>(start + t * step));
        if (!e.defined) return std::nullopt;
        if (std::abs(e.value) < std::abs(best.value)) {
          best = e;
          best_t = t;
        }
        return RootSample{e.value, e.gradient.dot(step)};
      },
      0.0, 1.0, f0.value, f1.value, options);
  out.evaluations = root.evaluations;
  out.fallback = !root.ok;
  out.jump = root.jump;
  out.t = root.ok ? root.t : linear_t;
  // The normal of the evaluation nearest the root, if it is that near (the
  // root finder may stop on an extrapolated step it did not evaluate).
  out.normal = root.ok && std::abs(root.t - best_t) <= kNormalReach && best.gradient.squaredNorm() > 0.0
                   ? oriented_unit_normal<D>(best.gradient, best.mean_normal, fallback_axis)
                   : interpolated_normal(f0, f1, out.t, fallback_axis);
  return out;
}

}  // namespace amls
