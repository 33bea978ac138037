#include "core/run/deforming_surface.hpp"

#include "core/resample/point_splice.hpp"
#include "core/util/parallel_stopwatch.hpp"

namespace amls {

PhaseTimings& PhaseTimings::operator+=(const PhaseTimings& o) {
  normals += o.normals;
  function += o.function;
  resample += o.resample;
  deform += o.deform;
  hash += o.hash;
  return *this;
}

namespace {

// Ends the current phase: its seconds, and those of them outside parallel loops.
void end_phase(ParallelStopwatch& clock, double& seconds, double& serial_seconds) {
  const ParallelLap lap = clock.lap();
  seconds = lap.wall;
  serial_seconds = lap.wall - lap.parallel;
}

}  // namespace

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
void DeformingSurface<D>::resample_phases(StepStats& stats, const HeldRegions<D>& held) {
  ParallelStopwatch clock;
  stats.normals = surface_.update_normals(pool_);
  end_phase(clock, stats.timings.normals, stats.serial.normals);
  resampler_.update_function(surface_, pool_);
  end_phase(clock, stats.timings.function, stats.serial.function);
  PointSet<D> resampled = resampler_.resample(surface_, variant_, pool_);
  stats.resample = resampler_.stats();
  if (!held.empty()) {
    // Every old point goes but the held ones; the new ones join them as at a local resample's seam.
    PointSet<D> kept = surface_.points();
    splice_points<D>(kept, nullptr, resampled, SpliceRings{}, held, surface_.grid(), pool_);
    resampled = std::move(kept);
  }
  surface_.set_points(std::move(resampled));
  end_phase(clock, stats.timings.resample, stats.serial.resample);
}

template <int D>
StepStats DeformingSurface<D>::step(const Deformation<D>& deformation, double t0, double t1, bool resample) {
  StepStats stats;
  stats.points_before = surface_.points().size();
  if (resample) resample_phases(stats);
  ParallelStopwatch clock;
  deformation.deform(surface_.mutable_points(), t0, t1, pool_);
  end_phase(clock, stats.timings.deform, stats.serial.deform);
  surface_.hash_points(pool_);
  end_phase(clock, stats.timings.hash, stats.serial.hash);
  stats.points_after = surface_.points().size();
  return stats;
}

template <int D>
StepStats DeformingSurface<D>::resample_only(const HeldRegions<D>& held) {
  StepStats stats;
  stats.points_before = surface_.points().size();
  resample_phases(stats, held);
  ParallelStopwatch clock;
  surface_.hash_points(pool_);
  end_phase(clock, stats.timings.hash, stats.serial.hash);
  stats.points_after = surface_.points().size();
  return stats;
}

template <int D>
StepStats DeformingSurface<D>::resample_start(bool second_pass_where_sparse) {
  const StepStats first = resample_only();
  if (!second_pass_where_sparse || !calls_for_second_pass(first.normals, first.points_before)) return first;
  StepStats stats = resample_only();
  stats.timings += first.timings;
  stats.serial += first.serial;
  stats.normals = first.normals;
  stats.points_before = first.points_before;
  stats.first_pass_points = first.points_after;
  return stats;
}

template <int D>
NormalStats DeformingSurface<D>::refresh_normals() {
  return surface_.update_normals(pool_);
}

template class DeformingSurface<2>;
template class DeformingSurface<3>;

}  // namespace amls
