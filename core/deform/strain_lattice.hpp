#pragma once
// How far one step of any deformation is from rigid near each point. The
// step's images of the nodes of a lattice over the points (the deformation
// applied to the nodes as to points) give every lattice cell the step's mean
// Jacobian J there, and the cell's strain |J^T J - I| / 2 (Frobenius) is added
// to every point in it. Summed over steps, a point's strain bounds how much
// the spacing around it has changed since it was made, which is what local
// resampling (core/resample/local_resampling.hpp) reads.
//
// A cell several h wide holds many points, so the nodes cost a small part of
// the points' own deformation. The lattice sees what varies slower than a
// cell: a velocity field or an MLS map away from its handles; a map that bends
// sharply within one cell is averaged over it.
#include <array>
#include <cstddef>
#include <vector>

#include "core/deform/deformation.hpp"

namespace amls {

struct StrainLatticeStats {
  std::size_t cells = 0;  // lattice cells holding points
  std::size_t nodes = 0;  // their corners, deformed
  // The points' box held too many lattice cells for their number (scattered
  // points): the strain is unknown and every point's is set to infinity, so
  // that a local resampler redoes everything.
  bool fell_back = false;
};

// Adds the strain of `deformation` from t0 to t1 to each point's entry of
// `strain` (resized to the points). `positions` are the points before the
// step; `spacing` is the lattice's (e.g. 8 h). The result does not depend on
// the pool's thread count.
template <int D>
StrainLatticeStats add_step_strain(const Deformation<D>& deformation, double t0, double t1,
                                   const std::vector<Vec<D>>& positions, double spacing, std::vector<float>& strain,
                                   ThreadPool& pool);

// |J^T J - I| / 2 for the mean Jacobian J of a cube of side `spacing` whose
// corner v (offset 1 along axis a where bit a of v is set) went to images[v].
template <int D>
float cube_strain(const std::array<Vec<D>, 1 << D>& images, double spacing);
// The strain of the step between two maps of that cube: |J^T J - I| / 2 for
// J = J_after J_before^{-1}, the mean Jacobians from the corners' images
// under each; infinity where `before` has folded the cube flat or inside out.
template <int D>
float step_cube_strain(const std::array<Vec<D>, 1 << D>& before, const std::array<Vec<D>, 1 << D>& after,
                       double spacing);

extern template StrainLatticeStats add_step_strain<2>(const Deformation<2>&, double, double, const std::vector<Vec<2>>&,
                                                      double, std::vector<float>&, ThreadPool&);
extern template StrainLatticeStats add_step_strain<3>(const Deformation<3>&, double, double, const std::vector<Vec<3>>&,
                                                      double, std::vector<float>&, ThreadPool&);
extern template float cube_strain<2>(const std::array<Vec<2>, 4>&, double);
extern template float cube_strain<3>(const std::array<Vec<3>, 8>&, double);
extern template float step_cube_strain<2>(const std::array<Vec<2>, 4>&, const std::array<Vec<2>, 4>&, double);
extern template float step_cube_strain<3>(const std::array<Vec<3>, 8>&, const std::array<Vec<3>, 8>&, double);

}  // namespace amls
