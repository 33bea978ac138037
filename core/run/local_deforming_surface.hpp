#pragma once
// The deformation loop with local resampling (`--resample local`): each step
// maps the points by the MLS map (its rotations by the polar iteration), a
// lattice giving each point the strain of the step
// (core/deform/mls_lattice.hpp), and resamples
// only where the summed strain says the sampling has changed
// (core/resample/local_resampling.hpp). Points elsewhere keep their positions
// and carried normals; no whole-surface fit, F, walk or index is made.
//
// Any other deformation (a velocity field's flow) takes a step of its own:
// the strain comes from the deformation's images of the nodes of the same
// lattice (core/deform/strain_lattice.hpp), then the points are deformed.
#include <vector>

#include "core/deform/mls_lattice.hpp"
#include "core/deform/strain_lattice.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/run/deforming_surface.hpp"

namespace amls {

struct LocalStepStats {
  PhaseTimings timings;  // deform: the map and the strain; normals, function, resample: the local resample's
  MlsLatticeStats map;              // of an MLS step
  StrainLatticeStats strain_lattice;  // of any other deformation's step
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
  // Replaces the point set and the strain each point carries (one per point),
  // as points() and strain() gave them: a saved state taken up again.
  void set_points(PointSet<D> points, std::vector<float> strain);
  // Resamples the whole surface now, with no deformation.
  LocalStepStats resample_all();
  // One step: map by `deformation` (from its `from` to its `to` handles), then resample where strained.
  LocalStepStats step(const MlsDeformation<D>& deformation);
  // One step of any deformation from t0 to t1: the strain measured on the
  // lattice, the points deformed, then resampled where strained.
  LocalStepStats step(const Deformation<D>& deformation, double t0, double t1);

  // The surface of the current points, hashed and with their pseudo-normals,
  // to evaluate or measure F (made anew: the loop itself keeps no index).
  AmlsSurface<D> fitted_surface();

  const PointSet<D>& points() const { return points_; }
  const std::vector<float>& strain() const { return strain_; }
  const Grid<D>& grid() const { return grid_; }
  ThreadPool& pool() { return pool_; }

 private:
  LocalStepStats resample_strained();

  Grid<D> grid_;
  AmlsParameters parameters_;
  LocalResampler<D> resampler_;
  MlsLatticeOptions lattice_;
  PointSet<D> points_;
  std::vector<float> strain_;
  ThreadPool pool_;
};

extern template class LocalDeformingSurface<2>;
extern template class LocalDeformingSurface<3>;

}  // namespace amls
