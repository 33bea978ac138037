#pragma once
// One resampling of a point set with oriented normals (the `amls resample`
// command): the points' AMLS surface S(P) resampled once on a grid of spacing h
// (paper, section 3.2), with no deformation.
#include <cstddef>
#include <string>
#include <vector>

#include "core/geometry/coverage.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"

namespace amls {

// Past this many estimated output points a resampling is refused before any
// grid is built, and past the points whose memory passes half the machine's.
inline constexpr double kMostResampledPoints = 50e6;
// Peak memory per output point: 1.4 KiB for a point set (building.ply,
// 100,000 points in, 326,234 out, 440 MiB), up to 4 KiB for a mesh, whose
// samples count too (armadillo: 207,074 samples, 66,187 out, 263 MiB).
inline constexpr double kMiBPerResampledPoint = 2.0 / 1024.0;

struct PointSetResampling {
  // h, by the first that is set:
  double spacing = 0.0;  // h itself, when positive
  int grid = 0;          // N cells: h = 1/N for points within the unit box, else the bounding box's longest side / N
  // neither: h by the rule of core/geometry/sample_spacing.hpp, which takes
  // first the spacing the input file records (`amls spacing`, 0: none)
  double recorded_spacing = 0.0;
  double radius_factor = 3.0;
  // Each point's own support, wider where the input is sparse
  // (AmlsParameters::widen_support): `amls resample` turns it on unless
  // --uniform-support; off for callers whose own surface uses one Delta.
  bool widen_support = false;
  bool keep_rims = AmlsParameters{}.keep_rims;  // AmlsParameters::keep_rims
  // A second pass where the input is sparser than h
  // (DeformingSurface::resample_start; `--one-pass` turns it off).
  bool second_pass_where_sparse = true;
  Variant variant = Variant::exact;
  int threads = 1;
  double most_points = kMostResampledPoints;  // the cost limits (check_resampling_cost)
  double memory_mib = 0.0;                    // memory it may take; 0: half the machine's
};

// The h a resampling uses and why, for the user.
struct SpacingChoice {
  double h = 0.0;
  std::string reason;  // "--spacing 0.01", "--grid 256 over the unit box", "h = ...: the median distance ..."
};

// Throws std::invalid_argument naming the option for a bad --spacing or
// --grid, and when the rule has too few distinct points to measure.
template <int D>
SpacingChoice choose_spacing(const std::vector<Vec<D>>& positions, const PointSetResampling& options);

// The longest side of the points' bounding box (at least one point; throws
// std::invalid_argument for a non-finite coordinate).
template <int D>
double longest_side(const std::vector<Vec<D>>& positions);

// The surface's area (3D) or length (2D) as the points sample it: their count
// times the area (length) each one covers, from the median distance to the
// kSpacingNeighbours-th neighbour (robust to outliers and duplicates).
template <int D>
double sampled_extent(const std::vector<Vec<D>>& positions);

// What a resampling at h of a surface of the given area (3D) or length (2D)
// will produce, estimated before any grid is built.
struct ResamplingCost {
  double points = 0.0;           // output points, about 1.5 per h^2 of area (4/pi per h of length in 2D)
  double limit = 0.0;            // the most points allowed: most_points, or fewer to fit memory_mib
  double fitting_spacing = 0.0;  // the smallest h whose estimate stays within the limit
};
// Throws std::invalid_argument when the estimate passes the limit, naming the
// estimate, the limit and the --spacing that would fit.
ResamplingCost check_resampling_cost(int dimension, double extent, double h, const PointSetResampling& options);

// How the supports were widened (AmlsParameters::widen_support) for the input.
struct SupportWidening {
  std::size_t widened_points = 0;  // input points whose Delta_i exceeds Delta
  double widest = 1.0;             // the largest Delta_i / Delta
};

// An open surface's rim through the resample (core/surface/surface_rim.hpp).
struct RimReport {
  std::size_t samples_in = 0;   // rim samples of the input
  std::size_t samples_out = 0;  // rim samples of the output, found as the input's were
  // How far, in h, the output reaches past the rim line of the input's rim
  // samples (the largest G of an output point, 0 where none lies beyond).
  double advance_h = 0.0;
};

template <int D>
struct ResampledPointSet {
  PointSet<D> points;
  Grid<D> grid;
  StepStats stats;
  SupportWidening widening;
  SpacingStats spacing_h;  // nearest-neighbour spacing of the new points, in units of h
  Coverage coverage;       // of the input by the new points (core/geometry/coverage.hpp)
  RimReport rim;
};

// The grid a resampling at h uses: origin 0 when the points lie in the unit
// square or cube (so that the grid is the one the flow tests use), else the
// points' bounding box's lower corner less 2 Delta, so that every vertex the
// walk reads has a small index. Throws std::invalid_argument if h is not
// positive or the points span more cells than a packed vertex key can number.
template <int D>
Grid<D> resampling_grid(const PointSet<D>& points, double h, double radius_factor);

// Resamples at choose_spacing()'s h, after check_resampling_cost(), and
// measures the coverage. Throws std::invalid_argument for an empty set or a
// zero or non-finite normal (S(P) needs every point oriented). The result may
// be empty when S(P) has no zero crossing on the grid near the points.
template <int D>
ResampledPointSet<D> resample_point_set(PointSet<D> points, const PointSetResampling& options);

extern template double longest_side<2>(const std::vector<Vec<2>>&);
extern template double longest_side<3>(const std::vector<Vec<3>>&);
extern template SpacingChoice choose_spacing<2>(const std::vector<Vec<2>>&, const PointSetResampling&);
extern template SpacingChoice choose_spacing<3>(const std::vector<Vec<3>>&, const PointSetResampling&);
extern template double sampled_extent<2>(const std::vector<Vec<2>>&);
extern template double sampled_extent<3>(const std::vector<Vec<3>>&);
extern template Grid<2> resampling_grid<2>(const PointSet<2>&, double, double);
extern template Grid<3> resampling_grid<3>(const PointSet<3>&, double, double);
extern template ResampledPointSet<2> resample_point_set<2>(PointSet<2>, const PointSetResampling&);
extern template ResampledPointSet<3> resample_point_set<3>(PointSet<3>, const PointSetResampling&);

}  // namespace amls
