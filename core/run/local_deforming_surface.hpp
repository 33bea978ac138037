#pragma once
// The deformation loop with local resampling (`--resample local`): each step
// maps the points by the MLS map (its rotations by the polar iteration), a
// lattice giving each point the strain of the map since its rest state
// (core/deform/mls_lattice.hpp), and resamples
// only where the summed strain says the sampling has changed
// (core/resample/local_resampling.hpp). Points elsewhere keep their positions
// and carried normals; no whole-surface fit, F, walk or index is made.
//
// The MLS map from a rest state: during a drag the points keep their rest
// positions (where they were when the drag, or the last resample, began) and
// every step maps them from there by the one map that takes the handles' rest
// positions to their current ones, interpolated on the lattice (within
// 0.01 h of the exact map at the cells' centres, exact where it misses). Its
// error is that of one interpolation at every step (up to a few times the
// tolerance between the centres) instead of adding up from step to step. A step that resamples maps every point exactly
// first, and then starts a new rest state for all points (the current handles become the rest handles), so nothing
// interpolated is ever built upon.
#include <optional>
#include <vector>

#include "core/deform/mls_lattice.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/run/deforming_surface.hpp"

namespace amls {

struct LocalStepStats {
  PhaseTimings timings;  // deform: the map and the strain; normals, function, resample: the local resample's
  MlsLatticeStats map;
  LocalResampleStats resample;
  std::size_t points_before = 0;
  std::size_t points_after = 0;
};

template <int D>
class LocalDeformingSurface {
 public:
  // The strain's lattice is 8 h wide.
  LocalDeformingSurface(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant, int threads = 1,
                        const LocalResampleOptions& options = {});

  // Replaces the point set; the next step (or resample_all) resamples all of it.
  void set_points(PointSet<D> points);
  // Resamples the whole surface now, with no deformation.
  LocalStepStats resample_all();
  // One step: the handles move from deformation.from() to deformation.to();
  // the points follow and are resampled where strained. A step whose `from`
  // handles (or kind, or alpha) are not the last step's `to` starts a new
  // rest state, at `from`.
  LocalStepStats step(const MlsDeformation<D>& deformation);
  // The handles' rest positions of the current rest state (empty until a step after set_points or resample_all).
  std::vector<Vec<D>> rest_handles() const;

  const PointSet<D>& points() const { return points_; }
  const std::vector<float>& strain() const { return strain_; }
  const Grid<D>& grid() const { return grid_; }
  ThreadPool& pool() { return pool_; }

 private:
  // The rest state of the MLS steps: the points, their summed strain and the
  // handles when it began, its lattice, and the handles the points were last
  // mapped to.
  struct Rest {
    PointSet<D> points;
    MlsRestLattice<D> lattice;
    std::vector<float> strain;
    std::vector<Vec<D>> handles;
    std::vector<Vec<D>> current;
    MlsKind kind = MlsKind::rigid;
    double alpha = 1.0;
    bool exact = true;  // points_ is the exact map of the rest points to `current`
  };

  LocalStepStats resample_strained();
  // The map from the rest handles to `to`, by the polar iteration.
  MlsDeformation<D> map_from_rest(const std::vector<Vec<D>>& to) const;
  // Starts a new rest state at `handles` from the current points, mapped exactly first.
  void rebase(const std::vector<Vec<D>>& handles, MlsKind kind, double alpha);

  Grid<D> grid_;
  LocalResampler<D> resampler_;
  MlsLatticeOptions lattice_;
  PointSet<D> points_;
  std::vector<float> strain_;
  std::optional<Rest> rest_;  // none before the first MLS step and after the points change otherwise
  ThreadPool pool_;
};

extern template class LocalDeformingSurface<2>;
extern template class LocalDeformingSurface<3>;

}  // namespace amls
