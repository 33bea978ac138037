#include "core/run/local_deforming_surface.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

// The lattice that measures the strain, in h: a strain cell holds a few
// hundred points, so it costs a few percent of the map. The points themselves
// take the exact map: interpolating it errs in the same direction step after
// step, and without resampling the errors add up (core/deform/mls_lattice.hpp).
constexpr double kLatticeSpacing = 8.0;

}  // namespace

template <int D>
LocalDeformingSurface<D>::LocalDeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant,
                                                int threads, const LocalResampleOptions& options)
    : grid_(grid),
      parameters_(parameters),
      resampler_(grid, parameters, variant),
      lattice_{kLatticeSpacing * grid.spacing(), 0.0, 4, false},
      pool_(threads) {
  resampler_.set_options(options);
}

template <int D>
void LocalDeformingSurface<D>::set_points(PointSet<D> points) {
  points_ = std::move(points);
  strain_.assign(points_.size(), std::numeric_limits<float>::infinity());
}

template <int D>
void LocalDeformingSurface<D>::set_points(PointSet<D> points, std::vector<float> strain) {
  if (strain.size() != points.size())
    throw std::invalid_argument("local deforming surface: " + std::to_string(points.size()) + " points but " +
                                std::to_string(strain.size()) + " strains");
  points_ = std::move(points);
  strain_ = std::move(strain);
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::resample_strained() {
  LocalStepStats stats;
  stats.points_before = points_.size();
  stats.resample = resampler_.resample(points_, strain_, pool_);
  stats.timings.normals = stats.resample.normals_seconds;
  stats.timings.function = stats.resample.function_seconds;
  stats.timings.resample = stats.resample.resample_seconds;
  stats.points_after = points_.size();
  return stats;
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::resample_all() {
  std::fill(strain_.begin(), strain_.end(), std::numeric_limits<float>::infinity());
  return resample_strained();
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::step(const MlsDeformation<D>& deformation) {
  Stopwatch clock;
  const std::size_t before = points_.size();
  MlsDeformation<D> map_by_polar_iteration = deformation;
  map_by_polar_iteration.use_polar_iteration(true);
  const MlsLatticeStats map = apply_on_lattice(map_by_polar_iteration, points_, &strain_, lattice_, pool_);
  const double deform_seconds = clock.lap();
  LocalStepStats stats = resample_strained();
  stats.points_before = before;
  stats.map = map;
  stats.timings.deform = deform_seconds;
  return stats;
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::step(const Deformation<D>& deformation, double t0, double t1) {
  Stopwatch clock;
  const std::size_t before = points_.size();
  const StrainLatticeStats lattice =
      add_step_strain(deformation, t0, t1, points_.positions, lattice_.spacing, strain_, pool_);
  deformation.deform(points_, t0, t1, pool_);
  const double deform_seconds = clock.lap();
  LocalStepStats stats = resample_strained();
  stats.points_before = before;
  stats.strain_lattice = lattice;
  stats.timings.deform = deform_seconds;
  return stats;
}

template <int D>
AmlsSurface<D> LocalDeformingSurface<D>::fitted_surface() {
  AmlsSurface<D> surface(grid_, parameters_);
  surface.set_points(points_);
  surface.hash_points(pool_);
  surface.update_normals(pool_);
  return surface;
}

template class LocalDeformingSurface<2>;
template class LocalDeformingSurface<3>;

}  // namespace amls
