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

// A start's resample (DeformingSurface::resample_start) makes a second pass
// where the supports were widened at this share of its points or more. A raw
// scan sparser than h has 1.5 to 40 % (CGAL's demo scans); an output of amls
// read back at its own h a few at its rim (hippo2.ply's: 5 of 11,082), and a
// second pass there would double the work for nothing.
inline constexpr double kSecondPassWidenedShare = 0.01;

// Whether a first resample whose normals' fits were `first`, over `points`
// points, calls for a second pass.
inline bool calls_for_second_pass(const NormalStats& first, std::size_t points) {
  return static_cast<double>(first.widened) >= kSecondPassWidenedShare * static_cast<double>(points) &&
         first.widened > 0;
}

struct StepStats {
  PhaseTimings timings;
  NormalStats normals;
  ResampleStats resample;
  std::size_t points_before = 0;  // points entering the step
  std::size_t points_after = 0;   // points leaving it (after resampling and deformation)
  // Of each phase's seconds, those outside parallel loops: on one thread, the
  // part that more threads cannot share (core/util/parallel_stopwatch.hpp).
  PhaseTimings serial;
  std::size_t first_pass_points = 0;  // a start's resample that made a second pass: the first pass's points
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
  // The first resample of a shape's samples: resample_only(), then once more
  // where its fits widened kSecondPassWidenedShare of the points or more (and
  // `second_pass_where_sparse`). The first pass upsamples a scan sparser than h
  // with F from wide supports and leaves small holes, one or two crossings
  // wide, where those weights fall short or a sparse rim sample's wide reach
  // cuts its crossings; F of the dense first pass fills them, so the next
  // resample would still add 1 to 4 % of points and move more. The second
  // pass is that resample, done at the start (docs/design.md, "A second pass
  // where the input is sparse"). The stats: both passes' times, the first
  // pass's fits (those of the shape's samples), the second's resample.
  StepStats resample_start(bool second_pass_where_sparse = true);

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
