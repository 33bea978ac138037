#include "core/run/local_deforming_surface.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

// The lattice that interpolates the map and measures each step's strain, in
// h: the strain limits were tuned with its cells (docs/local-resampling.md),
// and a cell holds a few hundred points, so its nodes cost a small part of
// mapping every point exactly.
constexpr double kLatticeSpacing = 8.0;
// How far (in h) the interpolated map may be from the exact one at a cell's
// centre. The points are mapped from their rest positions at every step, so
// this bounds their error at every step; it does not add up.
constexpr double kLatticeTolerance = 0.001;
constexpr int kLatticeRefinement = 4;

}  // namespace

template <int D>
LocalDeformingSurface<D>::LocalDeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant,
                                                int threads, const LocalResampleOptions& options)
    : grid_(grid),
      parameters_(parameters),
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
void LocalDeformingSurface<D>::set_points(PointSet<D> points, std::vector<float> strain) {
  if (strain.size() != points.size())
    throw std::invalid_argument("local deforming surface: " + std::to_string(points.size()) + " points but " +
                                std::to_string(strain.size()) + " strains");
  points_ = std::move(points);
  strain_ = std::move(strain);
  rest_.reset();
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::resample_strained(const HeldRegions<D>& held) {
  LocalStepStats stats;
  stats.points_before = points_.size();
  stats.resample = resampler_.resample(points_, strain_, pool_, held);
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
LocalStepStats LocalDeformingSurface<D>::resample_start(bool second_pass_where_sparse) {
  const LocalStepStats first = resample_all();
  if (!second_pass_where_sparse || !calls_for_second_pass(first.resample.normals, first.points_before)) return first;
  LocalStepStats stats = resample_all();
  stats.timings += first.timings;
  stats.resample.normals = first.resample.normals;
  stats.points_before = first.points_before;
  stats.first_pass_points = first.points_after;
  return stats;
}

template <int D>
std::vector<Vec<D>> LocalDeformingSurface<D>::rest_handles() const {
  return rest_ ? rest_->handles : std::vector<Vec<D>>{};
}

template <int D>
std::vector<RegionHandle<D>> LocalDeformingSurface<D>::rest_regions() const {
  return rest_ ? rest_->regions : std::vector<RegionHandle<D>>{};
}

template <int D>
typename LocalDeformingSurface<D>::Saved LocalDeformingSurface<D>::save() const {
  const bool mapped_on_lattice = rest_ && !exact_;
  return Saved{mapped_on_lattice ? std::nullopt : std::optional<PointSet<D>>(points_), strain_, rest_, current_, current_regions_,
               node_images_, exact_};
}

template <int D>
void LocalDeformingSurface<D>::restore(Saved saved) {
  strain_ = std::move(saved.strain);
  rest_ = std::move(saved.rest);
  current_ = std::move(saved.current);
  current_regions_ = std::move(saved.current_regions);
  node_images_ = std::move(saved.node_images);
  exact_ = saved.exact;
  if (saved.points)
    points_ = std::move(*saved.points);
  else
    rest_->lattice.map(map_from_rest(current_, current_regions_), rest_->points, points_, nullptr, nullptr, pool_);
}

template <int D>
MlsDeformation<D> LocalDeformingSurface<D>::map_from_rest(const std::vector<Vec<D>>& to,
                                                         const std::vector<RegionHandle<D>>& to_regions) const {
  MlsDeformation<D> map(rest_->handles, to, rest_->regions, to_regions, rest_->kind, rest_->alpha);
  map.use_polar_iteration(true);
  return map;
}

template <int D>
void LocalDeformingSurface<D>::leave_rest_state() {
  map_exactly();
  rest_.reset();
  exact_ = true;
}

template <int D>
bool LocalDeformingSurface<D>::map_exactly() {
  if (!rest_ || exact_) return false;
  PointSet<D> exact = rest_->points;
  map_from_rest(current_, current_regions_).apply(exact, pool_);
  points_ = std::move(exact);
  exact_ = true;
  return true;
}

template <int D>
void LocalDeformingSurface<D>::rebase(const std::vector<Vec<D>>& handles, const std::vector<RegionHandle<D>>& regions,
                                      MlsKind kind, double alpha) {
  leave_rest_state();
  rest_ = std::make_shared<const Rest>(
      Rest{points_, MlsRestLattice<D>(points_, lattice_, pool_), handles, regions, kind, alpha});
  current_ = handles;
  current_regions_ = regions;
  node_images_.clear();
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::step(const MlsDeformation<D>& deformation) {
  Stopwatch clock;
  const std::size_t before = points_.size();
  if (!rest_ || current_ != deformation.from() || !same_places(current_regions_, deformation.from_regions()) ||
      rest_->kind != deformation.kind() || rest_->alpha != deformation.alpha())
    rebase(deformation.from(), deformation.from_regions(), deformation.kind(), deformation.alpha());
  // The strain of this step alone, summed: the whole drag's map can be nearly
  // rigid where its steps were not (a handle pulled out and back), and the
  // sampling followed the steps.
  const MlsDeformation<D> map = map_from_rest(deformation.to(), deformation.to_regions());
  const MlsLatticeStats mapped = rest_->lattice.map(map, rest_->points, points_, &strain_, &node_images_, pool_);
  current_ = deformation.to();
  current_regions_ = deformation.to_regions();
  exact_ = mapped.exact_points == points_.size();
  const double limit = resampler_.options().strain_limit;
  const bool resamples = std::any_of(strain_.begin(), strain_.end(), [&](float s) { return s > limit; });
  // The resample reads the points, and its result becomes the next rest state: map them exactly.
  if (resamples && !exact_) {
    points_ = rest_->points;
    map.apply(points_, pool_);
    exact_ = true;
  }
  const double deform_seconds = clock.lap();
  LocalStepStats stats;
  stats.points_after = points_.size();
  if (resamples) {
    // The regions' points stay as their motion put them (core/geometry/held_regions.hpp).
    stats = resample_strained(held_regions(current_regions_));
    rest_.reset();
    rebase(deformation.to(), deformation.to_regions(), deformation.kind(), deformation.alpha());
  }
  stats.points_before = before;
  stats.map = mapped;
  stats.timings.deform = deform_seconds;
  return stats;
}

template <int D>
LocalStepStats LocalDeformingSurface<D>::step(const Deformation<D>& deformation, double t0, double t1) {
  Stopwatch clock;
  leave_rest_state();
  const std::size_t before = points_.size();
  const StrainLatticeStats lattice = add_step_strain(deformation, t0, t1, points_.positions,
                                                     kLatticeSpacing * grid_.spacing(), strain_, pool_);
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
  return fitted_surface(points_);
}

template <int D>
AmlsSurface<D> LocalDeformingSurface<D>::fitted_surface(PointSet<D> points) {
  AmlsSurface<D> surface(grid_, parameters_);
  surface.set_points(std::move(points));
  surface.hash_points(pool_);
  surface.update_normals(pool_);
  return surface;
}

template class LocalDeformingSurface<2>;
template class LocalDeformingSurface<3>;

}  // namespace amls
