#include "core/run/point_set_resampling.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/util/parameter_ranges.hpp"

namespace amls {

namespace {

// Cells the walk and the neighbour index may reach beyond the points' own:
// Delta / h rounded up, and the walk's block of 4 cells.
std::int64_t margin_cells(double radius_factor) { return static_cast<std::int64_t>(std::ceil(radius_factor)) + 8; }

double spacing_of(const PointSetResampling& options) {
  if (options.spacing != 0.0) {
    check_range("--spacing", options.spacing, ranges::kSpacing);
    return options.spacing;
  }
  check_range("--grid", options.grid, ranges::kGridCells);
  return 1.0 / options.grid;
}

}  // namespace

template <int D>
Grid<D> resampling_grid(const PointSet<D>& points, const PointSetResampling& options) {
  const double h = spacing_of(options);
  check_range("--radius-factor", options.radius_factor, ranges::kRadiusFactor);
  if (points.empty()) return Grid<D>(Vec<D>::Zero(), h);
  Vec<D> lo = points.positions.front(), hi = lo;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points.positions[i].allFinite())
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    lo = lo.cwiseMin(points.positions[i]);
    hi = hi.cwiseMax(points.positions[i]);
  }
  const bool in_unit_box = (lo.array() >= 0.0).all() && (hi.array() <= 1.0).all();
  const Vec<D> origin = in_unit_box ? Vec<D>::Zero() : Vec<D>(lo.array() - 2.0 * options.radius_factor * h);
  const Grid<D> grid(origin, h);
  const double most = static_cast<double>(Grid<D>::kMaxIndex - margin_cells(options.radius_factor));
  for (int a = 0; a < D; ++a) {
    const double cells = (hi[a] - origin[a]) / h;
    if (!(cells < most))
      throw std::invalid_argument("the points span " + std::to_string(hi[a] - lo[a]) + " along axis " +
                                  std::to_string(a) + ", more than " + std::to_string(static_cast<long long>(most)) +
                                  " cells of h = " + std::to_string(h) +
                                  "; use a larger --spacing (or smaller --grid)");
  }
  return grid;
}

template <int D>
ResampledPointSet<D> resample_point_set(PointSet<D> points, const PointSetResampling& options) {
  if (points.empty()) throw std::invalid_argument("no points to resample: the input is empty");
  if (points.normals.size() != points.size())
    throw std::invalid_argument("resampling needs oriented normals: the input has " + std::to_string(points.size()) +
                                " points but " + std::to_string(points.normals.size()) + " normals");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points.normals[i].allFinite() || points.normals[i].isZero(0.0))
      throw std::invalid_argument("resampling needs oriented normals: point " + std::to_string(i) +
                                  " has a zero or non-finite normal");
  check_range("--threads", options.threads, ranges::kThreads);
  const Grid<D> grid = resampling_grid(points, options);
  DeformingSurface<D> surface(grid, AmlsParameters{options.radius_factor}, options.variant, options.threads);
  surface.set_points(std::move(points));
  const StepStats stats = surface.resample_only();
  SpacingStats spacing = spacing_stats(surface.points(), grid.spacing());
  return ResampledPointSet<D>{surface.points(), grid, stats, spacing};
}

template Grid<2> resampling_grid<2>(const PointSet<2>&, const PointSetResampling&);
template Grid<3> resampling_grid<3>(const PointSet<3>&, const PointSetResampling&);
template ResampledPointSet<2> resample_point_set<2>(PointSet<2>, const PointSetResampling&);
template ResampledPointSet<3> resample_point_set<3>(PointSet<3>, const PointSetResampling&);

}  // namespace amls
