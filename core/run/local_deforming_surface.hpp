#pragma once
// The deformation loop with local resampling (`--resample local`): each step
// maps the points by the MLS map (its rotations by the polar iteration), its
// 8 h lattice adding to each point the strain of the step
// (core/deform/mls_lattice.hpp), and resamples
// only where the summed strain says the sampling has changed
// (core/resample/local_resampling.hpp). Points elsewhere keep their positions
// and carried normals; no whole-surface fit, F, walk or index is made.
//
// The MLS map from a rest state: during a drag the points keep their rest
// positions (where they were when the drag, or the last resample, began) and
// every step maps them from there by the one map that takes the handles' rest
// positions to their current ones, interpolated on the lattice (within
// 0.001 h of the exact map at the cells' centres, exact where it misses). Its
// error is that of one interpolation at every step instead of adding up from
// step to step. A step that resamples maps every point exactly first, and
// then starts a new rest state for all points (the current handles become the
// rest handles), so nothing interpolated is ever built upon.
//
// Any other deformation (a velocity field's flow) takes a step of its own:
// the strain comes from the deformation's images of the nodes of an 8 h
// lattice (core/deform/strain_lattice.hpp), then the points are deformed; it
// ends any rest state.
#include <memory>
#include <optional>
#include <vector>

#include "core/deform/mls_lattice.hpp"
#include "core/deform/strain_lattice.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/run/deforming_surface.hpp"

namespace amls {

struct LocalStepStats {
  PhaseTimings timings;  // deform: the map and the strain; normals, function, resample: the local resample's
  MlsLatticeStats map;                // of an MLS step (the map and the strain)
  StrainLatticeStats strain_lattice;  // of any other deformation's step
  LocalResampleStats resample;
  std::size_t points_before = 0;
  std::size_t points_after = 0;
  std::size_t first_pass_points = 0;  // resample_start() with a second pass: the first pass's points
};

template <int D>
class LocalDeformingSurface {
 public:
  LocalDeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant, int threads = 1,
                        const LocalResampleOptions& options = {});

  // Replaces the point set; the next step (or resample_all) resamples all of it.
  void set_points(PointSet<D> points);
  // Replaces the point set and the strain each point carries (one per point),
  // as points() and strain() gave them: a saved state taken up again. The next
  // MLS step starts a new rest state from these points.
  void set_points(PointSet<D> points, std::vector<float> strain);
  // Resamples the whole surface now, with no deformation.
  LocalStepStats resample_all();
  // The first resample of a shape's samples: resample_all(), with a second
  // pass where DeformingSurface::resample_start() makes one, and the same
  // stats (both passes' times, the first pass's fits).
  LocalStepStats resample_start(bool second_pass_where_sparse = true);
  // One step: the handles move from deformation.from() to deformation.to();
  // the points follow and are resampled where strained. A step whose `from`
  // handles (or regions, kind, or alpha) are not the last step's `to` starts a new
  // rest state, at `from`.
  LocalStepStats step(const MlsDeformation<D>& deformation);
  // One step of any deformation from t0 to t1: the strain measured on the
  // lattice, the points deformed, then resampled where strained.
  LocalStepStats step(const Deformation<D>& deformation, double t0, double t1);

  // The end of a drag: if the last step interpolated the points, maps them
  // exactly from the rest state (all of them, a few hundred milliseconds at a
  // million points) and returns true. The rest state stays, and the next step
  // of the drag maps from it as if this had not run. Stopped by the pool's
  // cancellation check, it leaves the points as they were.
  bool map_exactly();
  // The surface of the current points, hashed and with their pseudo-normals,
  // to evaluate or measure F (made anew: the loop itself keeps no index).
  AmlsSurface<D> fitted_surface();
  // The same for `points` (e.g. a part of the current points), on this surface's grid and parameters.
  AmlsSurface<D> fitted_surface(PointSet<D> points);

  // The handles' rest positions of the current rest state (empty until a step after set_points or resample_all).
  std::vector<Vec<D>> rest_handles() const;
  // And its regions at rest (empty as rest_handles()).
  std::vector<RegionHandle<D>> rest_regions() const;

  const PointSet<D>& points() const { return points_; }
  const std::vector<float>& strain() const { return strain_; }
  const Grid<D>& grid() const { return grid_; }
  ThreadPool& pool() { return pool_; }

 private:
  // The rest state of the MLS steps: the points and the handles when it
  // began, and its lattice. Shared, never changed: a saved state holds it
  // without copying the lattice.
  struct Rest {
    PointSet<D> points;
    MlsRestLattice<D> lattice;
    std::vector<Vec<D>> handles;
    std::vector<RegionHandle<D>> regions;
    MlsKind kind = MlsKind::rigid;
    double alpha = 1.0;
  };

 public:
  // Everything a step reads: taken before a step and given back, the next
  // step runs as if the one in between never had (a stopped step). Within a
  // drag the points are the lattice's map of the rest state to `current`:
  // then they are not copied (a million points at every step) but mapped
  // again by restore(), the same way, to the same values.
  struct Saved {
    std::optional<PointSet<D>> points;  // none: the lattice's map of rest to current
    std::vector<float> strain;
    std::shared_ptr<const Rest> rest;
    std::vector<Vec<D>> current;
    std::vector<RegionHandle<D>> current_regions;
    MlsNodeImages<D> node_images;
    bool exact = true;
  };
  Saved save() const;
  void restore(Saved saved);

 private:
  // Resamples where strained, keeping the points that `held` holds.
  LocalStepStats resample_strained(const HeldRegions<D>& held = {});
  // The map from the rest handles to `to` (and the rest regions to `to_regions`), by the polar iteration.
  MlsDeformation<D> map_from_rest(const std::vector<Vec<D>>& to, const std::vector<RegionHandle<D>>& to_regions) const;
  // Ends the rest state: points_ becomes the exact map of the rest points if it was interpolated.
  void leave_rest_state();
  // Starts a new rest state at `handles` from the current points, mapped exactly first.
  void rebase(const std::vector<Vec<D>>& handles, const std::vector<RegionHandle<D>>& regions, MlsKind kind,
              double alpha);

  Grid<D> grid_;
  AmlsParameters parameters_;
  LocalResampler<D> resampler_;
  MlsLatticeOptions lattice_;
  PointSet<D> points_;
  std::vector<float> strain_;
  // None before the first MLS step and after the points change otherwise.
  std::shared_ptr<const Rest> rest_;
  std::vector<Vec<D>> current_;  // the handles the points were last mapped to
  std::vector<RegionHandle<D>> current_regions_;  // and the regions
  MlsNodeImages<D> node_images_;  // the rest lattice's nodes mapped to current_ (empty: at rest)
  bool exact_ = true;            // points_ is the exact map of the rest points to current_
  ThreadPool pool_;
};

extern template class LocalDeformingSurface<2>;
extern template class LocalDeformingSurface<3>;

}  // namespace amls
