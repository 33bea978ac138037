#include "core/run/local_deforming_surface.hpp"

#include <algorithm>
#include <limits>

#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

// The lattice of the map and its strain, in h: a cell holds a few hundred
// points, so its nodes cost a few percent of mapping every point exactly.
constexpr double kLatticeSpacing = 12.0;
// How far (in h) the interpolated map may be from the exact one at a cell's
// centre. The points are mapped from their rest positions at every step, so
// this bounds their error at every step; it does not add up.
constexpr double kLatticeTolerance = 0.01;
constexpr int kLatticeRefinement = 4;

}  // namespace

template <int D>
LocalDeformingSurface<D>::LocalDeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant,
                                                int threads, const LocalResampleOptions& options)
    : grid_(grid),
      resampler_(grid, parameters, variant),
      lattice_{kLatticeSpacing * grid.spacing(), kLatticeTolerance * grid.spacing(), kLatticeRefinement, true},
      pool_(threads) {
  resampler_.set_options(options);
}

template <int D>
void LocalDeformingSurface<D>::set_points(PointSet<D> points) {
  points_ = std::move(points);
  strain_.assign(points_.size(), std::numeric_limits<float>::infinity());
  rest_.reset();
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
  rest_.reset();
  return resample_strained();
}

template <int D>
std::vector<Vec<D>> LocalDeformingSurface<D>::rest_handles() const {
  return rest_ ? rest_->handles : std::vector<Vec<D>>{};
}

template <int D>
MlsDeformation<D> LocalDeformingSurface<D>::map_from_rest(const std::vector<Vec<D>>& to) const {
  MlsDeformation<D> map(rest_->handles, to, rest_->kind, rest_->alpha);
  map.use_polar_iteration(true);
  return map;
}

template <int D>
void LocalDeformingSurface<D>::rebase(const std::vector<Vec<D>>& handles, MlsKind kind, double alpha) {
  if (rest_ && !rest_->exact) {
    points_ = rest_->points;
    map_from_rest(rest_->current).apply(points_, pool_);
  }
  rest_.reset();
  rest_.emplace(
      Rest{points_, MlsRestLattice<D>(points_, lattice_, pool_), strain_, handles, handles, kind, alpha, true});
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::step(const MlsDeformation<D>& deformation) {
  Stopwatch clock;
  const std::size_t before = points_.size();
  if (!rest_ || rest_->current != deformation.from() || rest_->kind != deformation.kind() ||
      rest_->alpha != deformation.alpha())
    rebase(deformation.from(), deformation.kind(), deformation.alpha());
  const MlsDeformation<D> map = map_from_rest(deformation.to());
  strain_ = rest_->strain;
  const MlsLatticeStats mapped = rest_->lattice.map(map, rest_->points, points_, &strain_, pool_);
  rest_->current = deformation.to();
  rest_->exact = mapped.exact_points == points_.size();
  const double limit = resampler_.options().strain_limit;
  const bool resamples = std::any_of(strain_.begin(), strain_.end(), [&](float s) { return s > limit; });
  // The resample reads the points, and its result becomes the next rest state: map them exactly.
  if (resamples && !rest_->exact) {
    points_ = rest_->points;
    map.apply(points_, pool_);
  }
  const double deform_seconds = clock.lap();
  LocalStepStats stats;
  stats.points_after = points_.size();
  if (resamples) {
    stats = resample_strained();
    rest_.reset();
    rebase(deformation.to(), deformation.kind(), deformation.alpha());
  }
  stats.points_before = before;
  stats.map = mapped;
  stats.timings.deform = deform_seconds;
  return stats;
}

template class LocalDeformingSurface<2>;
template class LocalDeformingSurface<3>;

}  // namespace amls
