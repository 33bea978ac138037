#pragma once
// One resampling of a point set with oriented normals (the `amls resample`
// command): the points' AMLS surface S(P) resampled once on a grid of spacing h
// (paper, section 3.2), with no deformation.
#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"

namespace amls {

struct PointSetResampling {
  int grid = 256;        // cells per unit length: h = 1 / grid (unless spacing is set)
  double spacing = 0.0;  // h itself, when positive
  double radius_factor = 3.0;
  Variant variant = Variant::exact;
  int threads = 1;
};

template <int D>
struct ResampledPointSet {
  PointSet<D> points;
  Grid<D> grid;
  StepStats stats;
  SpacingStats spacing_h;  // nearest-neighbour spacing of the new points, in units of h
};

// The grid a resampling uses: origin 0 when the points lie in the unit square
// or cube (so that the grid is the one the flow tests use), else the points'
// bounding box's lower corner less 2 Delta, so that every vertex the walk reads
// has a small index. Throws std::invalid_argument if h is not positive or the
// points span more cells than a packed vertex key can number.
template <int D>
Grid<D> resampling_grid(const PointSet<D>& points, const PointSetResampling& options);

// Throws std::invalid_argument for an empty set or a zero or non-finite normal
// (S(P) needs every point oriented). The result may be empty when S(P) has no
// zero crossing on the grid near the points (too sparse a set for this h).
template <int D>
ResampledPointSet<D> resample_point_set(PointSet<D> points, const PointSetResampling& options);

extern template Grid<2> resampling_grid<2>(const PointSet<2>&, const PointSetResampling&);
extern template Grid<3> resampling_grid<3>(const PointSet<3>&, const PointSetResampling&);
extern template ResampledPointSet<2> resample_point_set<2>(PointSet<2>, const PointSetResampling&);
extern template ResampledPointSet<3> resample_point_set<3>(PointSet<3>, const PointSetResampling&);

}  // namespace amls
