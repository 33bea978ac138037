#pragma once
// The MLS map of one step, cheap: evaluated exactly at the nodes of a coarse
// lattice over the points and interpolated (multilinearly, the position and
// the linear part L) in between. Away from the handles the map is smooth and
// a lattice of several h reproduces it far within the tolerance; where it is
// not, the lattice is refined, and where even that misses, the points take
// the exact map:
//
// - Each lattice cell holding points is checked at its centre, where the
//   multilinear interpolant of a smooth map errs most: if the interpolated
//   position is more than `tolerance` from the exact one, or a handle lies
//   within one cell of it, the cell is split into refinement^D sub-cells with
//   exact nodes of their own, checked the same way at their centres.
// - A sub-cell that fails its check (or holds a handle) maps its points exactly.
//
// Each step also gives every point the strain of its (sub-)cell: how far the
// map is from rigid there, |J^T J - I| / 2 (Frobenius) for the cell's mean
// Jacobian J from its nodes. Summed over steps it bounds how much the spacing
// around a point has changed since it was last resampled (local resampling).
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
  double tolerance = 0.0;  // of the interpolated positions, at the cells' centres (e.g. 0.01 h)
  int refinement = 4;      // sub-cells per axis of a refined cell
  // False: every point takes the exact map (MlsDeformation::apply), and the
  // lattice only gives the strain, of its coarse cells. Interpolation errs by
  // up to `tolerance` per step in a direction that stays the same from step
  // to step, so over many steps without a resample the errors add up: on the
  // drag benchmark at 200k points, 40 steps leave the surface 0.045 h (max)
  // from the exact shape at 0.01 h, 0.031 h at 0.001 h, against 0.0001 h
  // with the exact map.
  bool interpolate = true;
};

struct MlsLatticeStats {
  std::size_t cells = 0;          // lattice cells holding points
  std::size_t refined_cells = 0;  // of which split into sub-cells
  std::size_t exact_cells = 0;    // sub-cells whose points took the exact map
  std::size_t exact_points = 0;   // points that took the exact map
  std::size_t evaluations = 0;    // exact evaluations of the map (nodes, checks and exact points)
  // The points' box held too many lattice cells for their number (scattered
  // points): every point took the exact map and the strain is unknown (set to
  // infinity, so that a local resampler redoes everything).
  bool fell_back = false;
};

// Maps `points` by `deformation` (positions, and the normals carried by L),
// adding each point's strain to `strain` (resized to the points, when not null).
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
  // checked; std::invalid_argument otherwise).
  MlsLatticeStats map(const MlsDeformation<D>& deformation, const PointSet<D>& points, PointSet<D>& mapped,
                      std::vector<float>* strain, ThreadPool& pool) const;

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
