#pragma once
// A region handle (Pauly et al. 2003, "Shape modeling with point-sampled
// geometry"): a region of the surface (core/geometry/point_region.hpp) that
// the MLS map moves as one piece, by a rigid motion with an optional uniform
// scale (core/geometry/region_motion.hpp). A pinned region keeps its motion;
// a moving one follows the motion it is given. The map takes every point
// within the region's reach along exactly, and blends outside
// (mls_deformation.hpp says how).
#include <memory>
#include <vector>

#include "core/geometry/held_regions.hpp"
#include "core/geometry/point_region.hpp"
#include "core/geometry/region_motion.hpp"

namespace amls {

template <int D>
struct RegionHandle {
  // Its members where the motion is the identity. Shared: a region keeps its
  // members through every step, stage and undo state.
  std::shared_ptr<const PointRegion<D>> region;
  RegionMotion<D> motion;  // where it is now
  bool pinned = false;     // the editor does not let it be dragged; a scene's targets may not move it

  // The same region at the same place (pinned or not).
  bool same_place(const RegionHandle& other) const { return region == other.region && motion == other.motion; }
  bool operator==(const RegionHandle& other) const { return same_place(other) && pinned == other.pinned; }

  // Where a rest position of the region is now.
  Vec<D> place(const Vec<D>& rest) const { return motion.linear() * rest + motion.offset(region->centre()); }
  // The members where the region is now.
  std::vector<Vec<D>> placed_members() const {
    const Mat<D> linear = motion.linear();
    const Vec<D> offset = motion.offset(region->centre());
    std::vector<Vec<D>> out;
    out.reserve(region->members().size());
    for (const Vec<D>& m : region->members()) out.push_back(linear * m + offset);
    return out;
  }
};

// Whether two lists hold the same regions at the same places.
template <int D>
bool same_places(const std::vector<RegionHandle<D>>& a, const std::vector<RegionHandle<D>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!a[i].same_place(b[i])) return false;
  return true;
}

// The regions at their places as a resample keeps their points (those that
// scale hold none: core/geometry/held_regions.hpp).
template <int D>
HeldRegions<D> held_regions(const std::vector<RegionHandle<D>>& regions) {
  HeldRegions<D> held;
  for (const RegionHandle<D>& r : regions) held.add(r.region, r.motion);
  return held;
}

}  // namespace amls
