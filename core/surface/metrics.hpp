#pragma once
// Accuracy and sampling-quality measures, computed on the MLS
// surface of a point set.
#include <cstddef>
#include <string>
#include <vector>

#include "core/surface/amls_surface.hpp"

namespace amls {

// Nearest-neighbour spacing of a point set, in units of h.
struct SpacingStats {
  double min = 0.0;
  double median = 0.0;
  double max = 0.0;
};

template <int D>
SpacingStats spacing_stats(const PointSet<D>& points, double h);
// Every point's nearest-neighbour distance in units of h, sorted (empty for fewer than 2 points).
template <int D>
std::vector<double> nearest_neighbour_spacings(const PointSet<D>& points, double h);
// The same in the points' order, one value per point (e.g. to colour each point by it).
template <int D>
std::vector<double> nearest_neighbour_spacing_per_point(const PointSet<D>& points, double h);
// The same, the points shared among the pool's threads (the same values for any thread count).
template <int D>
std::vector<double> nearest_neighbour_spacing_per_point(const PointSet<D>& points, double h, ThreadPool& pool);
SpacingStats spacing_stats_of(const std::vector<double>& sorted_spacings);

// A frame's spacing as `amls deform` reports it: of every point, or of a
// sample of a large set (measuring every point, with an index of them all,
// would cost more than the step that made the frame). The sample is the
// points of blocks of the grid chosen by a hash of their place, about one
// point in ceil(size / max_measured); each measured point's distance is to
// its nearest among all the points, so a sample's figures are those of its
// points exactly.
struct SpacingSummary {
  SpacingStats h;             // min, median, max over the points measured, in units of h
  std::size_t measured = 0;   // points measured (0 for fewer than 2 points)
  std::size_t of = 0;         // points in the set
  std::size_t below = 0;      // measured points nearer than kSpacingBandLow h to their nearest (spacing_band.hpp)
  std::size_t above = 0;      // ... farther than kSpacingBandHigh h
  bool sampled() const { return measured < of && measured > 0; }
};
// Every point when there are at most max_measured, else a sample of about
// that many: the same points for any thread count and point order. On the pool.
template <int D>
SpacingSummary spacing_summary(const PointSet<D>& points, double h, std::size_t max_measured, ThreadPool& pool);

// Distances from each point of one set to the nearest point of another, in units of h.
struct DistanceStats {
  double mean = 0.0;
  double max = 0.0;
  std::size_t count = 0;  // points measured
};

// From every position in `from` to its nearest position in `to` (which must
// not be empty unless `from` is).
template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h);
// The same on the pool: the same figures, to the bit, for any thread count.
template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h,
                                     ThreadPool& pool);
// The same from a sample of `from` where it has more than max_measured
// points (0: no limit): its points in the blocks spacing_summary would sample
// a frame of its size by (one in ceil(size / max_measured), about
// max_measured points), each at its exact distance to the nearest of `to`;
// only the points of `to` within 2 h of the sampled blocks are indexed (a
// sampled point with none that near is measured against all of them). The
// same figures for any thread count. Every point of `from` when they are at
// most max_measured, or when the sample falls on none.
template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h,
                                     std::size_t max_measured, ThreadPool& pool);

// How the zero set of F meets rays cast from a centre. 2D: one closed curve
// around the centre is crossed exactly once by every ray (the paper's test is
// star-shaped at the end). 3D: a closed surface around the centre is crossed an
// odd number of times by every ray; volumes count the inside segments.
struct RayScan {
  bool closed = true;           // every ray passed the rule above
  std::size_t rays = 0;
  std::size_t bad_rays = 0;     // rays that failed it
  std::string reason;           // why it is not closed, if it is not
};

// 2D: the area between the zero set of F and the circle (center, radius) -
// the L1 error of the paper's Table 2 - by rays from the centre.
struct CircleError {
  RayScan scan;
  double l1 = 0.0;
};
CircleError circle_l1_error(const AmlsSurface<2>& surface, const Vec<2>& center, double radius, ThreadPool& pool,
                            std::size_t rays = 16384);

// 3D: the enclosed volume and its symmetric difference with the sphere
// (center, radius), by rays from the centre over a Fibonacci lattice of directions.
struct SphereError {
  RayScan scan;
  double volume = 0.0;
  double exact_volume = 0.0;
  double symmetric_difference = 0.0;
};
SphereError sphere_volume_error(const AmlsSurface<3>& surface, const Vec<3>& center, double radius, ThreadPool& pool,
                                std::size_t rays = 20000);

}  // namespace amls
