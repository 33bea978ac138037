#include "core/run/point_set_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/geometry/sample_spacing.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/surface/local_support.hpp"
#include "core/util/parameter_ranges.hpp"
#include "core/util/process_memory.hpp"

namespace amls {

namespace {

// Cells the walk and the neighbour index may reach beyond the points' own:
// Delta / h rounded up, and the walk's block of 4 cells.
std::int64_t margin_cells(double radius_factor) { return static_cast<std::int64_t>(std::ceil(radius_factor)) + 8; }

// Output points per h^2 of area (3D) or per h of length (2D): a surface crosses
// about (|nx| + |ny| + |nz|) grid edges per h^2, 1.5 on average over directions;
// a curve (|nx| + |ny|) per h, 4/pi on average.
constexpr double kPointsPerCell3 = 1.5;
constexpr double kPointsPerCell2 = 4.0 / std::numbers::pi;

std::string number(double x) {
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}

template <int D>
void bounds(const std::vector<Vec<D>>& positions, Vec<D>& lo, Vec<D>& hi) {
  lo = positions.front();
  hi = lo;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite())
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    lo = lo.cwiseMin(positions[i]);
    hi = hi.cwiseMax(positions[i]);
  }
}

}  // namespace

template <int D>
SpacingChoice choose_spacing(const std::vector<Vec<D>>& positions, const PointSetResampling& options) {
  if (options.spacing != 0.0) {
    check_range("--spacing", options.spacing, ranges::kSpacing);
    return {options.spacing, "--spacing " + number(options.spacing)};
  }
  if (options.grid != 0) {
    check_range("--grid", options.grid, ranges::kGridCells);
    if (positions.empty()) return {1.0 / options.grid, "--grid " + std::to_string(options.grid) + " over the unit box"};
    Vec<D> lo, hi;
    bounds(positions, lo, hi);
    if ((lo.array() >= 0.0).all() && (hi.array() <= 1.0).all())
      return {1.0 / options.grid, "--grid " + std::to_string(options.grid) + " over the unit box"};
    const double longest = longest_side(positions);
    if (!(longest > 0.0))
      throw std::invalid_argument("--grid " + std::to_string(options.grid) +
                                  ": the points all lie at one position, so their bounding box has no side to divide");
    return {longest / options.grid, "--grid " + std::to_string(options.grid) +
                                        " across the bounding box's longest side (" + number(longest) + ")"};
  }
  const SampleSpacing measured = sample_spacing<D>(positions, options.recorded_spacing);
  return {measured.h, measured.explanation()};
}

template <int D>
double sampled_extent(const std::vector<Vec<D>>& positions) {
  const double kth = median_of(kth_neighbour_distances<D>(positions, kSpacingNeighbours));
  const double n = static_cast<double>(positions.size());
  // k neighbours within distance d: a density of k / (pi d^2) per area, k / (2 d) per length.
  constexpr double k = kSpacingNeighbours;
  return D == 2 ? n * 2.0 * kth / k : n * std::numbers::pi * kth * kth / k;
}

ResamplingCost check_resampling_cost(int dimension, double extent, double h, const PointSetResampling& options) {
  ResamplingCost cost;
  const double memory = options.memory_mib > 0.0 ? options.memory_mib : 0.5 * physical_memory_mib();
  cost.limit = options.most_points;
  if (memory > 0.0) cost.limit = std::min(cost.limit, memory / kMiBPerResampledPoint);
  if (dimension == 2) {
    cost.points = kPointsPerCell2 * extent / h;
    cost.fitting_spacing = kPointsPerCell2 * extent / cost.limit;
  } else {
    cost.points = kPointsPerCell3 * extent / (h * h);
    cost.fitting_spacing = std::sqrt(kPointsPerCell3 * extent / cost.limit);
  }
  if (cost.points > cost.limit)
    throw std::invalid_argument(
        "h = " + number(h) + " would give about " + number(cost.points) + " points (the input samples a " +
        (dimension == 2 ? "curve of length " : "surface of area ") + number(extent) + "), more than the limit of " +
        number(cost.limit) + " (" + number(options.most_points) + " points, and " + number(memory / 1024.0) +
        " GiB of memory at about 2 KiB a point); --spacing " + number(cost.fitting_spacing * 1.01) +
        " or larger would fit");
  return cost;
}

template <int D>
Grid<D> resampling_grid(const PointSet<D>& points, double h, double radius_factor) {
  check_range("the grid spacing h", h, ranges::kSpacing);
  check_range("--radius-factor", radius_factor, ranges::kRadiusFactor);
  if (points.empty()) return Grid<D>(Vec<D>::Zero(), h);
  Vec<D> lo, hi;
  bounds(points.positions, lo, hi);
  const bool in_unit_box = (lo.array() >= 0.0).all() && (hi.array() <= 1.0).all();
  const Vec<D> origin = in_unit_box ? Vec<D>::Zero() : Vec<D>(lo.array() - 2.0 * radius_factor * h);
  const Grid<D> grid(origin, h);
  const double most = static_cast<double>(Grid<D>::kMaxIndex - margin_cells(radius_factor));
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

namespace {

template <int D>
AmlsSurface<D> fitted_surface(const PointSet<D>& points, const Grid<D>& grid, const AmlsParameters& parameters,
                              ThreadPool& pool) {
  AmlsSurface<D> surface(grid, parameters);
  surface.set_points(points);
  surface.hash_points(pool);
  surface.update_normals(pool);
  return surface;
}

// The rims of the input and of the output, each found on its own surface,
// and how far the output reaches past the input's rim line.
template <int D>
RimReport rim_report(const PointSet<D>& input, const PointSet<D>& output, const Grid<D>& grid,
                     const AmlsParameters& parameters, int threads) {
  RimReport report;
  if (!parameters.keep_rims || output.empty()) return report;
  ThreadPool pool(threads);
  const AmlsSurface<D> before = fitted_surface(input, grid, parameters, pool);
  report.samples_in = before.rim().size();
  report.samples_out = fitted_surface(output, grid, parameters, pool).rim().size();
  double farthest = 0.0;
  for (std::size_t k = 0; k < output.size(); ++k)
    farthest = std::max(farthest, before.rim().side(output.positions[k], output.normals[k]).value_or(0.0));
  report.advance_h = farthest / grid.spacing();
  return report;
}

}  // namespace

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
  const double h = choose_spacing(points.positions, options).h;
  const Grid<D> grid = resampling_grid(points, h, options.radius_factor);
  if (points.size() > static_cast<std::size_t>(kSpacingNeighbours))
    check_resampling_cost(D, sampled_extent(points.positions), h, options);
  const PointSet<D> input_points = points;
  const std::vector<Vec<D>>& input = input_points.positions;
  AmlsParameters parameters{options.radius_factor};
  parameters.widen_support = options.widen_support;
  parameters.keep_rims = options.keep_rims;
  DeformingSurface<D> surface(grid, parameters, options.variant, options.threads);
  surface.set_points(std::move(points));
  SupportWidening widening;
  if (options.widen_support) {
    ThreadPool pool(options.threads);
    const double radius = surface.surface().radius();
    for (const double widened : widened_support_radii<D>(input, radius, h, pool)) {
      widening.widened_points += widened > radius ? 1 : 0;
      widening.widest = std::max(widening.widest, widened / radius);
    }
  }
  const StepStats stats = surface.resample_start(options.second_pass_where_sparse);
  ResampledPointSet<D> out{surface.points(), grid, stats, widening, spacing_stats(surface.points(), h), Coverage{},
                           RimReport{}};
  out.rim = rim_report(input_points, out.points, grid, parameters, options.threads);
  if (input.size() > static_cast<std::size_t>(kSpacingNeighbours)) {
    out.coverage = measure_coverage<D>(input, out.points.positions, h);
    ThreadPool pool(options.threads);
    out.coverage.output_in_gaps = unsurrounded_points(out.points, h, kGapReach, pool);
  }
  return out;
}

template <int D>
double longest_side(const std::vector<Vec<D>>& positions) {
  Vec<D> lo, hi;
  bounds(positions, lo, hi);
  return (hi - lo).maxCoeff();
}

template double longest_side<2>(const std::vector<Vec<2>>&);
template double longest_side<3>(const std::vector<Vec<3>>&);
template SpacingChoice choose_spacing<2>(const std::vector<Vec<2>>&, const PointSetResampling&);
template SpacingChoice choose_spacing<3>(const std::vector<Vec<3>>&, const PointSetResampling&);
template double sampled_extent<2>(const std::vector<Vec<2>>&);
template double sampled_extent<3>(const std::vector<Vec<3>>&);
template Grid<2> resampling_grid<2>(const PointSet<2>&, double, double);
template Grid<3> resampling_grid<3>(const PointSet<3>&, double, double);
template ResampledPointSet<2> resample_point_set<2>(PointSet<2>, const PointSetResampling&);
template ResampledPointSet<3> resample_point_set<3>(PointSet<3>, const PointSetResampling&);

}  // namespace amls
