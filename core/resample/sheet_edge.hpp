#pragma once
// Where two sides of a sheet come within Delta and the sheet ends (a thin
// sheet torn, or stretched past what the grid resolves), each side's fit
// continues as a plane up to a support past the last points, and a crossing
// there moves the edge outward by a row at every resample. Such an edge is
// not found as a rim when the sheet curls back within the rim test's bridge.
// This is the test on the new point itself: it lies past the old points'
// edge when the sheet's other side is within reach (an old point whose
// normal opposes its own), no old point is within h of it, and those within
// kSheetEdgeReach all lie to one side of it in its tangent plane. (Without
// the other side, a new point far from old ones is where a sparse input is
// resampled finely, not an edge.)
#include <algorithm>
#include <cmath>

#include "core/surface/amls_surface.hpp"

namespace amls {

// How far (in h) the old points that judge a new point's side are taken from.
inline constexpr double kSheetEdgeReach = 2.5;
// The mean of their unit tangential directions is longer than this: one-sided
// (all within about 53 degrees of one direction would give 0.8; points all
// around give about 0).
inline constexpr double kSheetEdgeOneSided = 0.6;

// An old point whose normal turns more than 60 degrees from the new point's
// belongs to the sheet's other side or to its curled edge.
inline constexpr double kSheetOtherSide = 0.5;

// Whether y, with unit normal `normal`, lies past the edge of a sheet whose
// points are in `neighbourhood` (which must hold every point within
// kSheetEdgeReach h of y) and whose support is `radius` (Delta). Where a
// point's support was widened (AmlsParameters::widen_support), the points
// are sparser than h there, and a new point lies far from them for want of
// points, not past an edge: a sparse scan's first resample left such new
// points out all over (263 of CGAL's oni.ply, 5 % of its output), and the
// next resample, of a denser set, filled them in.
template <int D>
bool beyond_sheet_edge(const Neighbourhood<D>& neighbourhood, const Vec<D>& y, const Vec<D>& normal, double h,
                       double radius) {
  const double narrowest = 1.0 / (radius * radius);
  if (std::any_of(neighbourhood.inverse_r2.begin(), neighbourhood.inverse_r2.end(),
                  [&](double inverse_r2) { return inverse_r2 < narrowest; }))
    return false;
  const bool two_sided = std::any_of(neighbourhood.normals.begin(), neighbourhood.normals.end(),
                                     [&](const Vec<D>& n) { return n.dot(normal) < kSheetOtherSide; });
  if (!two_sided) return false;
  const double near2 = h * h;
  const double reach2 = kSheetEdgeReach * kSheetEdgeReach * h * h;
  Vec<D> directions = Vec<D>::Zero();
  int count = 0;
  for (const Vec<D>& p : neighbourhood.positions) {
    const Vec<D> d = p - y;
    const double d2 = d.squaredNorm();
    if (d2 <= near2) return false;
    if (d2 > reach2) continue;
    const Vec<D> tangential = d - normal * normal.dot(d);
    const double length = tangential.norm();
    if (length == 0.0) continue;
    directions += tangential / length;
    ++count;
  }
  return count > 0 && directions.norm() > kSheetEdgeOneSided * count;
}

}  // namespace amls
