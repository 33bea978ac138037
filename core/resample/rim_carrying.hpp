#pragma once
// The rim of an open surface, carried through a resample
// (core/surface/surface_rim.hpp says how it is found).
//
// The rim samples are carried into the new points, projected on S(P): the
// outermost new points are the old rim, so resampling a resample places its
// rim where it was, and a deformation moves the rim with its samples, as it
// moves every other point. Where a deformation stretched the rim, points are
// inserted between neighbours along it more than kRimGapToFill h apart;
// where it crowded them, samples closer than kRimSpacing h to one kept
// before are dropped.
//
// A grid-edge crossing is a new point only inside the domain that the
// carried rim draws: where its side function G is at most -kRimBand h (or
// where no rim point reaches), and no nearer than kRimBand h to a rim
// point. The band keeps the first row of new points about half an h in
// from the rim. The carried points, not all of the old rim samples, draw
// the line, because they are the rim samples that the next resample finds:
// so the next resample cuts its crossings where this one did.
//
// The cut has hysteresis: a crossing within kRimHold h of an old point (it
// gives back a point the last resample made) stays unless it lies more than
// kRimBand h past the line. A rim line redrawn from slightly different rim
// points at each resample moves by a fraction of h, and without it the
// crossings within that reach of the line came and went from one resample
// to the next; a new point still needs the line's full band, so the rim
// cannot advance by it.
#include <optional>

#include "core/geometry/point_set.hpp"
#include "core/surface/amls_surface.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

inline constexpr double kRimBand = 0.5;
inline constexpr double kRimGapToFill = 1.5;
inline constexpr double kRimSpacing = 0.75;
inline constexpr double kRimHold = 0.25;

struct RimCarryStats {
  std::size_t carried = 0;   // rim samples kept
  std::size_t inserted = 0;  // points added along stretched rims
  std::size_t crowding = 0;  // new points dropped for lying within kRimBand h of a rim point
};

template <int D>
struct CarriedRim {
  PointSet<D> points;  // the new rim points
  SurfaceRim<D> rim;   // the same, with their outward directions and supports: the domain
  RimCarryStats stats;
};

// The surface's rim samples as new points: projected on S(P), with points
// inserted along stretched stretches and crowded ones dropped. The same for
// any thread count.
template <int D>
CarriedRim<D> carry_rim(const AmlsSurface<D>& surface, ThreadPool& pool);

// Whether a crossing at x, whose surface normal is about `normal`, lies in
// the domain that `carried` draws on a grid of spacing h. `near_old_point()`
// says whether an old point lies within kRimHold h of x; it is asked only
// where x lies within kRimBand h of the rim line.
template <int D, typename NearOldPoint>
bool inside_rim(const CarriedRim<D>& carried, double h, const Vec<D>& x, const Vec<D>& normal,
                NearOldPoint&& near_old_point) {
  const std::optional<double> beyond = carried.rim.side(x, normal);
  if (!beyond || *beyond <= -kRimBand * h) return true;
  return *beyond <= kRimBand * h && near_old_point();
}

// Drops the points of `out` (new points of the grid walk) closer than
// kRimBand h to a rim point, then appends the rim points, marked as rim
// (PointSet::rim) so that the next resample keeps them there.
template <int D>
void append_rim(CarriedRim<D>& carried, double h, PointSet<D>& out);

extern template CarriedRim<2> carry_rim<2>(const AmlsSurface<2>&, ThreadPool&);
extern template CarriedRim<3> carry_rim<3>(const AmlsSurface<3>&, ThreadPool&);
extern template void append_rim<2>(CarriedRim<2>&, double, PointSet<2>&);
extern template void append_rim<3>(CarriedRim<3>&, double, PointSet<3>&);

}  // namespace amls
