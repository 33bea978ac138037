#pragma once
// The deformation loop of the paper, section 4: for each deformation
// phi_{t0 -> t1}: Update_Normals, Update_Function, Resample, Deform_Points, Hash.
#include "core/surface/amls_surface.hpp"
#include "core/deform/deformation.hpp"
#include "core/util/phase_times.hpp"
#include "core/geometry/held_regions.hpp"
#include "core/resample/resampler.hpp"

namespace amls {

// Seconds spent in each phase, as in the paper's Table 1.
struct PhaseTimings {
  double normals = 0.0;
  double function = 0.0;
  double resample = 0.0;
  double deform = 0.0;
  double hash = 0.0;
  double total() const { return normals + function + resample + deform + hash; }
  PhaseTimings& operator+=(const PhaseTimings& o);
  // normals, function, resample, deform, hash: the paper's loop order.
  PhaseTimes phases() const;
};

struct StepStats {
  PhaseTimings timings;
  NormalStats normals;
  ResampleStats resample;
  std::size_t points_before = 0;  // points entering the step
  std::size_t points_after = 0;   // points leaving it (after resampling and deformation)
  // Of each phase's seconds, those outside parallel loops: on one thread, the
  // part that more threads cannot share (core/util/parallel_stopwatch.hpp).
  PhaseTimings serial;
};

template <int D>
class DeformingSurface {
 public:
  DeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant, int threads = 1);

  // Replaces the point set (positions with oriented normals) and hashes it.
  void set_points(PointSet<D> points);

  // One step: resample S(P) (unless `resample` is false, which only deforms, to
  // show how the surface breaks without resampling), then deform the points
  // from t0 to t1 and hash them.
  StepStats step(const Deformation<D>& deformation, double t0, double t1, bool resample = true);

  // Resamples the current surface in place, with no deformation. The points
  // that `held` regions hold stay as they are (core/geometry/held_regions.hpp).
  StepStats resample_only(const HeldRegions<D>& held = {});

  // Recomputes the pseudo-normals of the current points so that surface() can be evaluated.
  NormalStats refresh_normals();

  const AmlsSurface<D>& surface() const { return surface_; }
  const PointSet<D>& points() const { return surface_.points(); }
  const Grid<D>& grid() const { return surface_.grid(); }
  Variant variant() const { return variant_; }
  void set_variant(Variant variant) { variant_ = variant; }
  ThreadPool& pool() { return pool_; }

 private:
  void resample_phases(StepStats& stats, const HeldRegions<D>& held = {});

  AmlsSurface<D> surface_;
  Resampler<D> resampler_;
  Variant variant_;
  ThreadPool pool_;
};

extern template class DeformingSurface<2>;
extern template class DeformingSurface<3>;

}  // namespace amls
