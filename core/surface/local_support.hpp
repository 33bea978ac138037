#pragma once
// Supports widened where the input is sparse (docs/real-data.md, "Uneven
// density"), as adaptive-bandwidth APSS does (Guennebaud and Gross 2007).
//
// One Delta closes a surface only where the points lie within about Delta / 2
// of each other; a scan dense in places and sparse elsewhere, resampled at
// the dense places' h, opens holes in the sparse ones. So each point p_i gets
// its own support
//
//   Delta_i = Delta * clamp(s_i / (kRegularSpread h), 1, kMostWidening),
//
// where s_i is p_i's own spacing by the rule that chooses h (its distance to
// its kSpacingNeighbours-th nearest neighbour, halved), and p_i weighs
// phi(|x - p_i| / Delta_i) in the Pratt fit and in F. Where the sampling is
// as dense as h says (s_i up to kRegularSpread h, which covers the spread of
// s_i on an even scan) Delta_i = Delta; the cap keeps one stray point from
// making every neighbour query reach across the scan.
#include <vector>

#include "core/geometry/sample_spacing.hpp"
#include "core/math/vec.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

inline constexpr double kRegularSpread = 1.25;
inline constexpr double kMostWidening = 4.0;
// A point's Delta_i depends only on the points within this many h of it: a
// kth neighbour this far or farther gives the cap.
inline constexpr double kSupportMeasureReach = kMostWidening * kRegularSpread * kSpacingNeighbourDivisor;
// The walk around a widened point covers the disc of this many Delta_i in
// its tangent plane: F is defined up to about 0.575 Delta_i from a lone
// point (AmlsParameters::min_weight), and the gaps of a sparse region lie
// within that of their points.
inline constexpr double kWalkDisc = 0.6;

// Every point's Delta_i for the support `radius` (Delta) on a grid of spacing
// h, in the points' order, measured on `pool` (the same for any thread
// count); empty when every Delta_i equals Delta (regular sampling, or at most
// kSpacingNeighbours points).
template <int D>
std::vector<double> widened_support_radii(const std::vector<Vec<D>>& positions, double radius, double h,
                                          ThreadPool& pool);

// Appends to `out` positions spaced 2h apart over the disc of kWalkDisc x
// Delta_i in the tangent plane (normal `normals[i]`) of every point whose
// Delta_i exceeds `radius`: their walks (core/geometry/walk_marks.hpp, which
// covers a block of at least h either side of a position) then reach every
// vertex near the widened surface, not only those near the sparse points.
template <int D>
void append_widened_walk_positions(const std::vector<Vec<D>>& positions, const std::vector<Vec<D>>& normals,
                                   const std::vector<double>& radii, double radius, double h,
                                   std::vector<Vec<D>>& out, ThreadPool& pool);

extern template std::vector<double> widened_support_radii<2>(const std::vector<Vec<2>>&, double, double,
                                                             ThreadPool&);
extern template std::vector<double> widened_support_radii<3>(const std::vector<Vec<3>>&, double, double,
                                                             ThreadPool&);
extern template void append_widened_walk_positions<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&,
                                                      const std::vector<double>&, double, double,
                                                      std::vector<Vec<2>>&, ThreadPool&);
extern template void append_widened_walk_positions<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&,
                                                      const std::vector<double>&, double, double,
                                                      std::vector<Vec<3>>&, ThreadPool&);

}  // namespace amls
