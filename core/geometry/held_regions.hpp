#pragma once
// The parts of a surface that region handles (core/deform/region_handle.hpp)
// carry as one piece, where a resample keeps the points as they are.
//
// Within a region's reach the MLS map moves every point by the region's rigid
// motion exactly, so the points there keep their spacing and lie on the
// surface moved rigidly. A resample would instead put new points on F, and F
// at a point near the region's rim is fitted to the bent neighbours just
// outside it too: a cap turned by 90 degrees drifted by a third of h at its
// rim, step after step. Kept as they are, the region's points follow its
// motion to rounding, and only the surface outside is resampled (and any hole
// among the region's points: core/resample/point_splice.hpp).
//
// A region whose motion scales it (scale other than 1) holds nothing: its
// points' spacing has changed with it, so it is resampled like the rest.
// Scale 1 is the region's scale when it was made, so its points then were a
// resample's, at the surface's spacing.
#include <memory>
#include <span>
#include <vector>

#include "core/geometry/point_region.hpp"
#include "core/geometry/region_motion.hpp"

namespace amls {

template <int D>
class HeldRegions {
 public:
  // Adds a region at the place `motion` puts it (from its members' place);
  // ignored when the motion scales it.
  void add(std::shared_ptr<const PointRegion<D>> region, const RegionMotion<D>& motion);

  bool empty() const { return zones_.empty(); }
  // Whether x lies within reach of a held region's members at their place. Thread-safe.
  bool holds(const Vec<D>& x) const;

 private:
  struct Zone {
    std::shared_ptr<const PointRegion<D>> region;
    Mat<D> to_rest;  // the inverse of the motion: x -> to_rest x + rest_offset
    Vec<D> rest_offset;
  };
  std::vector<Zone> zones_;
};

extern template class HeldRegions<2>;
extern template class HeldRegions<3>;

}  // namespace amls
