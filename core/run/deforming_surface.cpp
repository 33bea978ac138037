#include "core/run/deforming_surface.hpp"

#include "core/util/stopwatch.hpp"

namespace amls {

PhaseTimings& PhaseTimings::operator+=(const PhaseTimings& o) {
  normals += o.normals;
  function += o.function;
  resample += o.resample;
  deform += o.deform;
  hash += o.hash;
  return *this;
}

PhaseTimes PhaseTimings::phases() const {
  return {{"normals", normals}, {"function", function}, {"resample", resample}, {"deform", deform}, {"hash", hash}};
}

template <int D>
DeformingSurface<D>::DeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant,
                                      int threads)
    : surface_(grid, parameters), variant_(variant), pool_(threads) {}

template <int D>
void DeformingSurface<D>::set_points(PointSet<D> points) {
  surface_.set_points(std::move(points));
  surface_.hash_points(pool_);
}

template <int D>
void DeformingSurface<D>::resample_phases(StepStats& stats) {
  Stopwatch clock;
  stats.normals = surface_.update_normals(pool_);
  stats.timings.normals = clock.lap();
  resampler_.update_function(surface_, pool_);
  stats.timings.function = clock.lap();
  PointSet<D> resampled = resampler_.resample(surface_, variant_, pool_);
  stats.resample = resampler_.stats();
  surface_.set_points(std::move(resampled));
  stats.timings.resample = clock.lap();
}

template <int D>
StepStats DeformingSurface<D>::step(const Deformation<D>& deformation, double t0, double t1, bool resample) {
  StepStats stats;
  stats.points_before = surface_.points().size();
  if (resample) resample_phases(stats);
  Stopwatch clock;
  deformation.deform(surface_.mutable_points(), t0, t1, pool_);
  stats.timings.deform = clock.lap();
  surface_.hash_points(pool_);
  stats.timings.hash = clock.lap();
  stats.points_after = surface_.points().size();
  return stats;
}

template <int D>
StepStats DeformingSurface<D>::resample_only() {
  StepStats stats;
  stats.points_before = surface_.points().size();
  resample_phases(stats);
  Stopwatch clock;
  surface_.hash_points(pool_);
  stats.timings.hash = clock.lap();
  stats.points_after = surface_.points().size();
  return stats;
}

template <int D>
NormalStats DeformingSurface<D>::refresh_normals() {
  return surface_.update_normals(pool_);
}

template class DeformingSurface<2>;
template class DeformingSurface<3>;

}  // namespace amls
