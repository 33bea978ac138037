#pragma once
// How far apart the samples of a point set lie, and the grid spacing h chosen
// from it when the user gives none (docs/real-data.md, "Choosing h").
//
// The rule, one for every command and the editor: h = the median, over the
// points, of the distance to their kth nearest neighbour (k = kSpacingNeighbours),
// divided by kSpacingNeighbourDivisor. The kth neighbour rather than the first
// because scans are often dense along their scan lines and sparse across them:
// the nearest neighbour then sees only the dense direction. The median makes h
// independent of outliers and duplicates. Regions much sparser than the median
// would open holes at that h: one global h cannot close them without losing
// the dense regions' detail, so `amls resample` widens the supports of their
// points instead (core/surface/local_support.hpp; docs/real-data.md).
#include <cstddef>
#include <string>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

// The median of `values` (the upper one of an even count); `values` must not be empty.
double median_of(std::vector<double> values);

inline constexpr int kSpacingNeighbours = 4;
inline constexpr double kSpacingNeighbourDivisor = 2.0;

// Every point's distance to its kth nearest other point (k >= 1), in the
// points' order; 0 for a point with k exact duplicates. Needs more than k
// points, all finite (throws std::invalid_argument naming the first that is not).
template <int D>
std::vector<double> kth_neighbour_distances(const std::vector<Vec<D>>& positions, int k);

struct SampleSpacing {
  double nearest_median = 0.0;  // median distance to the nearest neighbour
  double kth_median = 0.0;      // median distance to the kSpacingNeighbours-th neighbour
  double h = 0.0;               // the grid spacing the rule gives: kth_median / divisor
  std::size_t points = 0;
  // "the median distance from each of the 5210 points to its 4th nearest neighbour (0.0199) / 2; ...", for messages.
  std::string explanation() const;
};

// Throws std::invalid_argument when the points are too few (at most
// kSpacingNeighbours) or so many coincide that the median distance is 0.
template <int D>
SampleSpacing sample_spacing(const std::vector<Vec<D>>& positions);

extern template std::vector<double> kth_neighbour_distances<2>(const std::vector<Vec<2>>&, int);
extern template std::vector<double> kth_neighbour_distances<3>(const std::vector<Vec<3>>&, int);
extern template SampleSpacing sample_spacing<2>(const std::vector<Vec<2>>&);
extern template SampleSpacing sample_spacing<3>(const std::vector<Vec<3>>&);

}  // namespace amls
