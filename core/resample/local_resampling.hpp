#pragma once
// Resampling only where the sampling changed. A drag moves the whole surface,
// but away from the dragged handle the map is nearly rigid: the points keep
// their spacing and their carried normals stay good enough to orient the next
// fit, so nothing there needs a new fit, a new F or a new walk.
//
// Each point carries its strain since it was made (the sum of the per-step
// strains of the map, core/deform/mls_lattice.hpp). Where it exceeds the
// limit, the point's region cell (a cube of 4 h) is flagged; the flagged cells
// grown by Delta are the region R that is resampled:
//
// - the walks of the points in R grown by one cell (so that every edge in R
//   near the surface is walked, even where the points near it lie just
//   outside R) give the vertices where F is needed; with widened supports
//   (AmlsParameters::widen_support), the walks over the widened points' discs
//   that reach those cells too, as the whole-surface Resampler walks them;
// - F there reads the points within Delta_i, their offsets and pseudo-normals
//   further points (4.5 supports in all): the support, every point within
//   4.5 W + 2 h of the walked cells for the widest Delta_i W that can reach
//   them, is fitted (Update_Normals). With widened supports W starts at
//   Delta: each Delta_i is measured, as the whole surface measures it, for
//   the points F could read if their own Delta_i were the widest allowed
//   (4 Delta), and W grows to the widest of those F can read, the measure
//   with it. The rings (core/resample/region_rings.hpp) grow only as far as
//   that asks, so the cost follows R and the supports near it, not the
//   widest support allowed;
// - Update_Function and Resample run on those vertices only (Resampler with
//   its own walk points); of the new points, those inside R replace the old
//   points of R. Points outside R keep their positions and carried normals.
//
// At the seam a kept point claims its nearest grid vertex: a crossing whose
// nearer edge end is a claimed vertex counts as HAVECLOSEPOINT there and is
// dropped, as is one closer to a kept point than the closest two of R's new
// points are to each other, h / sqrt(2) at most (core/resample/point_splice.hpp).
// The new points of the strip
// just outside R (the walked ring) are kept by the same rule
// (LocalResampleOptions::fill_seam): the kept points next to R are stretched
// by up to the strain limit (up to grow_above of it where the flagged cells
// grew), and without them the seam kept a gap wider than
// a whole resample leaves.
//
// Inside R, F and the crossings are those of a whole-surface resample of the
// same points: only which points are replaced differs. The points that region
// handles hold (core/geometry/held_regions.hpp) are kept even inside R.
#include <cstddef>
#include <vector>

#include "core/geometry/held_regions.hpp"
#include "core/resample/resampler.hpp"

namespace amls {

struct LocalResampleOptions {
  // Summed strain above which a point's region is resampled: the spacing
  // around it may have changed by about this fraction. The kept points next
  // to R are stretched by up to this much: on the drag scene
  // (assets/scenes/drag_sphere.json) 0.15 left the widest gap between the
  // exact shape and the points 11 % above the whole resample's, 0.12 below it.
  // A resample also keeps the error of the F it fits in its new points, and
  // F fitted to kept points strained by 0.12 where the surface bends most
  // erred twice as far as on a whole resample's points; at 0.10 it did not
  // (the 200k drag of `amls bench`; docs/local-resampling.md).
  double strain_limit = 0.10;
  // Whether the new points of the strip just outside R are kept where no kept
  // point crowds them (see LocalResampler). The flows, whose limit keeps the
  // points within a few percent of their spacing, turn it off: there the
  // strip's points, added step after step, made the 128^3 Enright test grow
  // past 20 times its points (docs/local-resampling.md).
  bool fill_seam = true;
  // The flagged cells grow, cell by cell, into the neighbouring cells whose
  // points passed this fraction of the limit: a region is resampled whole
  // when it first passes the limit rather than cell by cell over the next
  // steps, each of which would keep the error of an F fitted to ever more
  // strained neighbours (on the 200k drag, without this, two resamples in a
  // row left twice the whole resample's largest error). kNoGrowth: none.
  double grow_above = 0.7;
};

inline constexpr double kNoGrowth = 1.0;

// The options of a flow's local loop (`vortex`, `enright`): a flow strains
// the whole surface a little at every step, so grown into every cell past a
// fraction of its low limit a region would soon be the whole surface; and
// the strip's points are off (see fill_seam).
inline LocalResampleOptions flow_resample_options(double strain_limit) {
  return LocalResampleOptions{.strain_limit = strain_limit, .fill_seam = false, .grow_above = kNoGrowth};
}

struct LocalResampleStats {
  std::size_t flagged_cells = 0;    // region cells with a point over the strain limit, and those grown into
  std::size_t region_cells = 0;     // of R (flagged cells grown by Delta)
  std::size_t replaced = 0;         // old points in R, removed
  std::size_t held = 0;             // old points in R kept: a region handle holds them
  std::size_t support = 0;          // points fitted (Update_Normals)
  std::size_t inserted = 0;         // new points in R
  std::size_t filled_at_seam = 0;   // new points of the strip around R, kept where they fill the seam
  std::size_t dropped_at_seam = 0;  // new points dropped for a kept point's vertex or nearness, or within a held region
  NormalStats normals;
  ResampleStats resample;  // of the resampler's run over the walked vertices
  double normals_seconds = 0.0;   // choosing the support and fitting it, of which:
  double rings_seconds = 0.0;     //   the flagged cells, their rings and every point's ring
  double radii_seconds = 0.0;     //   widened supports: measuring Delta_i and growing the support to the widest
  double function_seconds = 0.0;
  double resample_seconds = 0.0;  // the resampler's walk and the splice
};

template <int D>
class LocalResampler {
 public:
  LocalResampler(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant);

  // Resamples S(points) in the region of the points whose strain exceeds the
  // limit; `strain` (one per point) is reset there: new points start at 0.
  // The points that `held` regions hold stay as they are, wherever they lie
  // (core/resample/point_splice.hpp). Kept points come first, in their
  // order, then the new ones.
  LocalResampleStats resample(PointSet<D>& points, std::vector<float>& strain, ThreadPool& pool,
                              const HeldRegions<D>& held = {});

  double region_cell_size() const { return cell_size_; }
  const LocalResampleOptions& options() const { return options_; }
  void set_options(const LocalResampleOptions& options) { options_ = options; }

 private:
  Grid<D> grid_;
  AmlsParameters parameters_;
  Variant variant_;
  LocalResampleOptions options_;
  double cell_size_;
  Resampler<D> resampler_;
};

extern template class LocalResampler<2>;
extern template class LocalResampler<3>;

}  // namespace amls
