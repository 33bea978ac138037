#pragma once
// When the deformation loop resamples. The paper resamples after every
// deformation step and names quality-triggered resampling as an improvement;
// `auto` does that: after each deformation it measures the point set's
// sampling quality (sampling_quality below) and resamples only when it has
// left a band (units of h):
//
// - gap <= max_gap = 2.5: every point is surrounded by neighbours of its own
//   sheet within 2.5 h. Right after a resample (and one step of deformation)
//   the largest gap is 2.2 h on the vortex and on Enright's test; beyond that
//   the surface is stretching apart there. Unlike nearest-neighbour spacing,
//   the gap sees a hole: a point at a hole's rim keeps a close neighbour on
//   its other side, but not on the hole's side.
// - feature_size >= min_feature_size = 1.4: no two nearby points of one sheet
//   turn their normals faster than a circle of radius 1.4 h does. The grid
//   walk cannot place crossings on a tip or fold much sharper than h: where the
//   flow sharpens the tip of a filament for many steps without a resample, the
//   next resample cuts the tip open and the curve stays broken. Under
//   `always` the tip's radius stays at or above 1.30 h (vortex, 256² and 512²);
//   the band keeps `auto`'s tips in that regime. At 1.2 h the 512² vortex
//   breaks; 1.3 to 1.6 h all pass at 256² and 512² (docs/design.md,
//   "Resampling only when needed").
//
// Crowding has no bound: between resamples the point count cannot grow, and
// crowded points define the same surface; the next resample thins them.
//
// Cost: one neighbour pass within 2.5 h, about a tenth of a resample
// (docs/performance.md).
#include <cstddef>
#include <string>

#include "core/geometry/point_set.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

// How well a point set with oriented normals samples its surface, in units of h.
// Neighbours count as the same sheet when their normals lie within 120 degrees
// of each other: the two sides of a filament thinner than the search radius
// (normals about 180 degrees apart) do not cover each other, and the points
// round a tip (normals turning by less than 120 degrees between neighbours) do.
struct SamplingQuality {
  // The largest, over the points, of the smallest radius r at which the point's
  // same-sheet neighbours within r surround it. 2D: one neighbour on each side
  // of the normal line. 3D: the neighbours' directions projected on the
  // tangent plane leave no empty sector of 150 degrees or more; a straight rim
  // leaves 180, the rim of a round hole of radius R sampled every s leaves
  // about 180 - s / R radians, so holes wider than about 4 s are seen (a
  // half-plane test would see none). Infinite when some point is not
  // surrounded within the search radius (a hole, an open end, or a tip
  // sharper than its neighbours).
  double gap = 0.0;
  // The smallest |p_i - p_j| / |n_i - n_j| over same-sheet pairs within the
  // search radius: the radius of curvature where the normals turn fastest (a
  // circle of radius r gives exactly r for every pair). Infinite when no pair
  // turns within the search radius (flat, or |p_i - p_j| / |n_i - n_j| beyond
  // radius / sqrt(3)).
  double feature_size = 0.0;
};

// Measures `points` (normals must be unit) against neighbours within `radius`
// (units of h). Max and min over the points, so the result does not depend on
// the pool's thread count. Fewer than 2 points: gap 0, feature_size infinite.
template <int D>
SamplingQuality sampling_quality(const PointSet<D>& points, double h, double radius, ThreadPool& pool);

// How many of `points` (normals must be unit) are not surrounded, in the
// sense of SamplingQuality::gap, by same-sheet neighbours within `radius`
// (units of h): the rims of holes and of open surfaces, and isolated points.
// All of them when fewer than 2.
template <int D>
std::size_t unsurrounded_points(const PointSet<D>& points, double h, double radius, ThreadPool& pool);

// `local` resamples, after each deformation, only where the deformation has
// strained the sampling since it was made (core/run/local_deforming_surface.hpp,
// docs/local-resampling.md): a loop of its own, so resample_now() does not
// decide it (it says true: the step resamples where strained).
struct ResamplePolicy {
  enum class Kind { always, automatic, every, local };
  Kind kind = Kind::always;
  int every = 1;  // Kind::every: resample on steps 0, K, 2K, ...
  // Kind::automatic: the band (units of h), explained above.
  double max_gap = 2.5;
  double min_feature_size = 1.4;

  // "always", "auto", "every:K" or "local"; throws std::invalid_argument naming the accepted forms.
  static ResamplePolicy parse(const std::string& text);
  std::string to_string() const;
  bool operator==(const ResamplePolicy&) const = default;

  // The neighbour radius (units of h) that decides the band exactly: a gap
  // above max_gap or a feature below min_feature_size is found within it
  // (|n_i - n_j| < sqrt(3) for normals within 120 degrees).
  double search_radius() const;

  // Whether step `step` (0-based) resamples, given the points as they are now
  // (the first step always does). Kind::automatic measures the points on `pool`.
  template <int D>
  bool resample_now(std::size_t step, const PointSet<D>& points, double h, ThreadPool& pool) const;
};

}  // namespace amls
