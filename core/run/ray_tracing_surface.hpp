#pragma once
// The deformation loop of the ray-tracing baseline (Gois et al. 2008), with the
// phases of the paper's Table 1, "Original" column: for each deformation
// phi_{t0 -> t1}: Comp. Normals (pseudo-normals from the k-d tree's
// neighbours), Intersections (RayResampler), Remove (clusters), Deform, Rebuild
// Tree. It shares the AMLS definition with DeformingSurface (the same Pratt fit,
// F, minimum weight and orientation filter, through AmlsSurface's
// pratt_fit_in() and evaluate_in()); only the neighbour index (k-d tree
// against grid hash) and the resampling (rays against the grid walk) differ.
#include "core/surface/amls_surface.hpp"
#include "core/deform/deformation.hpp"
#include "core/geometry/kd_tree.hpp"
#include "core/util/phase_times.hpp"
#include "core/resample/ray_resampler.hpp"

namespace amls {

// Seconds spent in each phase, named as in the paper's Table 1 (Original).
struct RayPhaseTimings {
  double deform = 0.0;
  double remove_clusters = 0.0;
  double rebuild_tree = 0.0;
  double intersections = 0.0;
  double normals = 0.0;
  double total() const { return deform + remove_clusters + rebuild_tree + intersections + normals; }
  RayPhaseTimings& operator+=(const RayPhaseTimings& o);
  // deform, remove_clusters, rebuild_tree, intersections, normals: Table 1's rows.
  PhaseTimes phases() const;
};

struct RayStepStats {
  RayPhaseTimings timings;
  NormalStats normals;
  RayResampleStats resample;
  std::size_t points_before = 0;  // points entering the step
  std::size_t points_after = 0;   // points leaving it
};

template <int D>
class RayTracingSurface {
 public:
  RayTracingSurface(const Grid<D>& grid, const AmlsParameters& parameters, const RaySettings& settings = {},
                    int threads = 1);

  // Replaces the point set (positions with oriented normals) and builds the tree.
  void set_points(PointSet<D> points);

  // One step: normals, intersections and cluster removal (the new point set;
  // skipped if `resample` is false, as in DeformingSurface::step), then the
  // deformation of the points from t0 to t1 and the tree rebuilt.
  RayStepStats step(const Deformation<D>& deformation, double t0, double t1, bool resample = true);
  // Resamples the current surface in place, with no deformation.
  RayStepStats resample_only();
  // Recomputes the pseudo-normals of the current points.
  NormalStats refresh_normals();
  // S(P) of the current points as the grid-based loop builds it (hashed, with
  // its own pseudo-normals): the same surface by the same code, so that results
  // are measured alike whichever loop made them.
  AmlsSurface<D> amls_surface();

  const PointSet<D>& points() const { return points_; }
  // Valid after refresh_normals() or a step's normals phase, until the points move.
  const std::vector<Vec<D>>& pseudo_normals() const { return pseudo_normals_; }
  const Grid<D>& grid() const { return definition_.grid(); }
  const AmlsParameters& parameters() const { return definition_.parameters(); }
  ThreadPool& pool() { return pool_; }

 private:
  NormalStats update_normals();
  void resample_phases(RayStepStats& stats);
  // Resampling (if asked), then the deformation (if any) and the tree rebuilt.
  RayStepStats run_step(bool resample, const Deformation<D>* deformation, double t0, double t1);

  AmlsSurface<D> definition_;  // F's definition (grid, Delta, parameters); holds no points
  PointSet<D> points_;
  std::vector<Vec<D>> pseudo_normals_;
  KdTree<D> tree_;
  RayResampler<D> resampler_;
  ThreadPool pool_;
  // Per thread block, a cache line apart: a neighbour query's ids and the
  // neighbourhood they make.
  struct alignas(64) NormalScratch {
    std::vector<std::uint32_t> near;
    Neighbourhood<D> neighbourhood;
  };
  std::vector<NormalScratch> normal_scratch_;
  std::vector<FitStatus> status_;
};

extern template class RayTracingSurface<2>;
extern template class RayTracingSurface<3>;

}  // namespace amls
