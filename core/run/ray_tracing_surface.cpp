#include "core/run/ray_tracing_surface.hpp"

#include <stdexcept>
#include <string>

#include "core/util/stopwatch.hpp"

namespace amls {

RayPhaseTimings& RayPhaseTimings::operator+=(const RayPhaseTimings& o) {
  deform += o.deform;
  remove_clusters += o.remove_clusters;
  rebuild_tree += o.rebuild_tree;
  intersections += o.intersections;
  normals += o.normals;
  return *this;
}

PhaseTimes RayPhaseTimings::phases() const {
  return {{"deform", deform},
          {"remove_clusters", remove_clusters},
          {"rebuild_tree", rebuild_tree},
          {"intersections", intersections},
          {"normals", normals}};
}

namespace {

// The baseline is the paper's plain AMLS surface: its fits see no offsets, and
// amls_surface() must measure that same surface.
AmlsParameters without_bias_correction(AmlsParameters parameters) {
  parameters.bias_correction = false;
  return parameters;
}

}  // namespace

template <int D>
RayTracingSurface<D>::RayTracingSurface(const Grid<D>& grid, const AmlsParameters& parameters,
                                        const RaySettings& settings, int threads)
    : definition_(grid, without_bias_correction(parameters)), resampler_(settings), pool_(threads) {}

template <int D>
void RayTracingSurface<D>::set_points(PointSet<D> points) {
  if (points.normals.size() != points.positions.size())
    throw std::invalid_argument("point set has " + std::to_string(points.positions.size()) + " positions but " +
                                std::to_string(points.normals.size()) + " normals");
  points_ = std::move(points);
  pseudo_normals_.clear();
  tree_.build(points_.positions);
}

// Comp. Normals: the Pratt fit of every point over its k-d tree neighbours.
template <int D>
NormalStats RayTracingSurface<D>::update_normals() {
  const std::size_t n = points_.size();
  const double radius = definition_.radius();
  pseudo_normals_.resize(n);
  status_.resize(n);
  normal_scratch_.resize(static_cast<std::size_t>(pool_.threads()));
  pool_.parallel_for(n, [&](std::size_t begin, std::size_t end, int block) {
    std::vector<std::uint32_t>& near = normal_scratch_[static_cast<std::size_t>(block)].near;
    Neighbourhood<D>& neighbourhood = normal_scratch_[static_cast<std::size_t>(block)].neighbourhood;
    // Solved a batch at a time, as DeformingSurface's (AmlsSurface::update_normals()).
    PrattBatches<D> fits(points_.normals, pseudo_normals_, status_, begin);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec<D>& p = points_.positions[i];
      near.clear();
      tree_.gather(p, radius, near);
      neighbourhood.positions.clear();
      neighbourhood.normals.clear();
      for (const std::uint32_t id : near) {
        neighbourhood.positions.push_back(points_.positions[id]);
        neighbourhood.normals.push_back(points_.normals[id]);
      }
      fits.start(i) = definition_.pratt_fit_in(neighbourhood, p, points_.normals[i]);
    }
    fits.finish(end);
  });
  NormalStats stats;
  for (const FitStatus s : status_) stats.count(s);
  return stats;
}

template <int D>
void RayTracingSurface<D>::resample_phases(RayStepStats& stats) {
  Stopwatch clock;
  stats.normals = update_normals();
  stats.timings.normals = clock.lap();
  resampler_.intersect(definition_, points_.positions, pseudo_normals_, pool_);
  stats.timings.intersections = clock.lap();
  points_ = resampler_.remove_clusters(definition_.grid().spacing(), pool_);
  pseudo_normals_.clear();
  stats.resample = resampler_.stats();
  stats.timings.remove_clusters = clock.lap();
}

template <int D>
RayStepStats RayTracingSurface<D>::run_step(bool resample, const Deformation<D>* deformation, double t0, double t1) {
  RayStepStats stats;
  stats.points_before = points_.size();
  if (resample) resample_phases(stats);
  Stopwatch clock;
  if (deformation) {
    deformation->deform(points_, t0, t1, pool_);
    pseudo_normals_.clear();  // of the points before they moved
    stats.timings.deform = clock.lap();
  }
  tree_.build(points_.positions);
  stats.timings.rebuild_tree = clock.lap();
  stats.points_after = points_.size();
  return stats;
}

template <int D>
RayStepStats RayTracingSurface<D>::step(const Deformation<D>& deformation, double t0, double t1, bool resample) {
  return run_step(resample, &deformation, t0, t1);
}

template <int D>
RayStepStats RayTracingSurface<D>::resample_only() {
  return run_step(true, nullptr, 0.0, 0.0);
}

template <int D>
NormalStats RayTracingSurface<D>::refresh_normals() {
  return update_normals();
}

template <int D>
AmlsSurface<D> RayTracingSurface<D>::amls_surface() {
  AmlsSurface<D> surface(definition_.grid(), definition_.parameters());
  surface.set_points(points_);
  surface.hash_points();
  surface.update_normals(pool_);
  return surface;
}

template class RayTracingSurface<2>;
template class RayTracingSurface<3>;

}  // namespace amls
