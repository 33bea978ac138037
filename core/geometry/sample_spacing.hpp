#pragma once
// How far apart the samples of a point set lie, and the grid spacing h chosen
// from it when the user gives none (docs/real-data.md, "Choosing h").
//
// The rule, one for every command, scene and the editor, the first that applies:
// 1. recorded: the spacing the file says its points were made at (amls writes
//    `amls spacing h` into the PLY and XYZ files it writes; core/io reads it);
// 2. grid lines: points that are crossings of a surface with the edges of a
//    grid (amls's own output, and marching cubes' vertices) lie on the grid's
//    lines: each point has D - 1 coordinates that are some grid vertex's,
//    shared bit for bit with the other points on that line. The step is the
//    median step between consecutive shared values along the axes; when at
//    least kGridLineShare of the points have exactly D - 1 coordinates on the
//    lattice of that step that most shared values lie on (per axis), and the step lies within
//    the band [kGridLineBandLow, kGridLineBandHigh] times the neighbour rule's
//    h, h is the step - so that reading back an output made at h gives h
//    again, where the neighbour rule gives 0.58 h (neighbours about 1.16 h
//    apart) and every round trip would triple the points;
// 3. neighbours: the median, over the points, of the distance to their kth
//    nearest neighbour (k = kSpacingNeighbours), divided by
//    kSpacingNeighbourDivisor. The kth neighbour rather than the first
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
// Grid-line samples: the share of points with exactly D - 1 coordinates on the
// lattice (a scattered scan has almost none, a quantised one has all D on it,
// and on a lattice far finer than its spacing: docs/real-data.md), the band, in units
// of the neighbour rule's h, the step must lie in (amls's output: 1.72 in 3D,
// 0.92 on a 2D curve), and how near a multiple of the step a coordinate must
// lie, in steps (files rounded to float keep about 1e-4).
inline constexpr double kGridLineShare = 0.9;
inline constexpr double kGridLineTolerance = 1e-3;
inline constexpr double kGridLineBandLow = 0.75;
inline constexpr double kGridLineBandHigh = 3.0;

// Every point's distance to its kth nearest other point (k >= 1), in the
// points' order; 0 for a point with k exact duplicates. Needs more than k
// points, all finite (throws std::invalid_argument naming the first that is not).
template <int D>
std::vector<double> kth_neighbour_distances(const std::vector<Vec<D>>& positions, int k);

// Which step of the rule gave h.
enum class SpacingRule { recorded, grid_lines, neighbours };

// Points on the lines of a grid: coordinates shared by several points, and the step between them.
struct GridLines {
  double share = 0.0;  // of the points, those with exactly D - 1 coordinates on the lattice of `step`
  double step = 0.0;   // median step between consecutive shared values along an axis (0: none)
};

struct SampleSpacing {
  SpacingRule rule = SpacingRule::neighbours;
  double nearest_median = 0.0;  // median distance to the nearest neighbour (0: not measured)
  double kth_median = 0.0;      // median distance to the kSpacingNeighbours-th neighbour (0: not measured)
  double neighbour_h = 0.0;     // the neighbour rule's h: kth_median / divisor (0: not measured)
  GridLines grid_lines;
  double h = 0.0;               // the grid spacing the rule gives
  std::size_t points = 0;
  // "the median distance from each of the 5210 points to its 4th nearest neighbour (0.0199) / 2; ...", for messages.
  std::string explanation() const;
};

// Shared coordinates and their step (finite positions; any number of them).
template <int D>
GridLines grid_lines_of(const std::vector<Vec<D>>& positions);

// The rule above; `recorded` > 0 is the spacing the file records (step 1).
// Throws std::invalid_argument, unless a spacing is recorded, when the points
// are too few (at most kSpacingNeighbours) or so many coincide that the
// median distance is 0; and for a recorded spacing that is not a positive number.
template <int D>
SampleSpacing sample_spacing(const std::vector<Vec<D>>& positions, double recorded = 0.0);

extern template std::vector<double> kth_neighbour_distances<2>(const std::vector<Vec<2>>&, int);
extern template std::vector<double> kth_neighbour_distances<3>(const std::vector<Vec<3>>&, int);
extern template GridLines grid_lines_of<2>(const std::vector<Vec<2>>&);
extern template GridLines grid_lines_of<3>(const std::vector<Vec<3>>&);
extern template SampleSpacing sample_spacing<2>(const std::vector<Vec<2>>&, double);
extern template SampleSpacing sample_spacing<3>(const std::vector<Vec<3>>&, double);

}  // namespace amls
