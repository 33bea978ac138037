#pragma once
// The MLS map of one step, cheap: evaluated exactly at the nodes of a coarse
// lattice over the points and interpolated in between. Away from the handles
// the map is smooth and a lattice of several h reproduces it far within the
// tolerance; where it is not, the lattice is refined, and where even that
// misses, the points take the exact map:
//
// - Positions are interpolated to third order: the mean of the multilinear
//   interpolant of the nodes' images and the multilinear blend of the nodes'
//   first-order Taylor expansions (each node's image plus its Jacobian times
//   the offset from it). For a quadratic map their errors are exact opposites,
//   so the mean errs only by the map's third derivatives: on the drag
//   benchmark's map at 8 h cells, about 1e-3 h where the multilinear
//   interpolant errs by 0.07 h. The Jacobians are central differences over
//   the lattice, so the nodes next to the cells' (a halo) are mapped too.
//   Normals are carried by the multilinear blend of the nodes' normal
//   transforms (|det L| L^{-T} of the local map's linear part L).
// - Each lattice cell holding points is checked at its centre: if the
//   interpolated position is more than `tolerance` from the exact one, or a
//   handle lies within one cell of it, the cell is split into refinement^D
//   sub-cells with exact nodes of their own (their Jacobians interpolated
//   from the cell's corners), checked the same way at their centres.
// - A sub-cell that fails its check (or holds a handle) maps its points exactly.
//
// Each map also gives every point the strain of its lattice cell: how far the
// step since the last map is from rigid there, |J^T J - I| / 2 (Frobenius)
// for the step's mean Jacobian J over the cell, from the nodes' images under
// both maps. Summed over steps it bounds how much the spacing around a point
// has changed since it was last resampled (local resampling).
//
// Points are independent, so the result does not depend on the thread count.
// With `interpolate` off, the lattice only measures the strain (see below).
// It is not the exact map's result bit for bit: callers that must reproduce
// the paper's runs keep MlsDeformation::apply().
#include <cstddef>
#include <memory>
#include <vector>

#include "core/deform/mls_deformation.hpp"

namespace amls {

struct MlsLatticeOptions {
  double spacing = 0.0;    // of the coarse lattice (e.g. 8 h)
  double tolerance = 0.0;  // of the interpolated positions, at the cells' centres (e.g. 0.001 h)
  int refinement = 4;      // sub-cells per axis of a refined cell
  // False: every point takes the exact map (MlsDeformation::apply), and the
  // lattice only gives the strain. Interpolation errs by up to `tolerance` in
  // a direction that stays the same from step to step: a map applied to the
  // last step's interpolated points adds up the errors; one from a rest
  // state (MlsRestLattice) does not.
  bool interpolate = true;
};

struct MlsLatticeStats {
  std::size_t cells = 0;          // lattice cells holding points
  std::size_t refined_cells = 0;  // of which split into sub-cells
  std::size_t exact_cells = 0;    // sub-cells whose points took the exact map
  std::size_t exact_points = 0;   // points that took the exact map
  std::size_t nodes = 0;          // lattice nodes mapped: the cells' corners and their halo
  std::size_t evaluations = 0;    // exact evaluations of the map (nodes, checks and exact points)
  // The points' box held too many lattice cells for their number (scattered
  // points): every point took the exact map and the strain is unknown (set to
  // infinity, so that a local resampler redoes everything).
  bool fell_back = false;
};

// The images of a lattice's nodes under the last map it applied: what the
// next map's step strain is measured from. Empty: the rest positions.
template <int D>
using MlsNodeImages = std::vector<Vec<D>>;

// Maps `points` by `deformation` (positions, and the normals carried by L),
// adding each point's strain to `strain` (resized to the points, when not
// null): the map's own, from the points where they are.
template <int D>
MlsLatticeStats apply_on_lattice(const MlsDeformation<D>& deformation, PointSet<D>& points, std::vector<float>* strain,
                                 const MlsLatticeOptions& options, ThreadPool& pool);
// The lattice over a fixed set of points, built once: the cells holding
// points, their nodes and each point's cell. A surface that keeps its points'
// rest positions during a drag maps them from there by the whole drag's map
// at every step; each step then costs the nodes' exact map, the checks and
// the interpolation, and its error is that of one map, whatever the number of
// steps.
template <int D>
class MlsRestLattice {
 public:
  // Throws std::invalid_argument for a spacing or tolerance not > 0, a
  // refinement < 1, or normals that do not match the points.
  MlsRestLattice(const PointSet<D>& points, const MlsLatticeOptions& options, ThreadPool& pool);
  ~MlsRestLattice();
  MlsRestLattice(MlsRestLattice&&) noexcept;
  MlsRestLattice& operator=(MlsRestLattice&&) noexcept;

  // As apply_on_lattice, with `points` left as they are and their images
  // written to `mapped` (resized to them; it may be `points` itself).
  // `points` must be the set the lattice was built over (its size is
  // checked; std::invalid_argument otherwise). The strain added is that of
  // the step from the map whose node images `last` holds (null or empty:
  // the rest state) to this one; `last`, when not null, then holds this
  // map's. What the map's regions decide here (their gaps at the nodes and
  // cell centres, which points their reach holds) depends only on their
  // first places: it is kept from one map to the next with the same first
  // places, and made anew for others. Thread-safe.
  MlsLatticeStats map(const MlsDeformation<D>& deformation, const PointSet<D>& points, PointSet<D>& mapped,
                      std::vector<float>* strain, MlsNodeImages<D>* last, ThreadPool& pool) const;

 private:
  struct Layout;
  std::unique_ptr<Layout> layout_;
};

extern template class MlsRestLattice<2>;
extern template class MlsRestLattice<3>;
extern template MlsLatticeStats apply_on_lattice<2>(const MlsDeformation<2>&, PointSet<2>&, std::vector<float>*,
                                                    const MlsLatticeOptions&, ThreadPool&);
extern template MlsLatticeStats apply_on_lattice<3>(const MlsDeformation<3>&, PointSet<3>&, std::vector<float>*,
                                                    const MlsLatticeOptions&, ThreadPool&);

}  // namespace amls
