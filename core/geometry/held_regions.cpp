#include "core/geometry/held_regions.hpp"

namespace amls {

template <int D>
void HeldRegions<D>::add(std::shared_ptr<const PointRegion<D>> region, const RegionMotion<D>& motion) {
  if (motion.scale != 1.0) return;
  // A rotation: its inverse is its transpose, exact to rounding.
  const Mat<D> to_rest = motion.rotation_matrix().transpose();
  const Vec<D> rest_offset = -(to_rest * motion.offset(region->centre()));
  zones_.push_back(Zone{std::move(region), to_rest, rest_offset});
}

template <int D>
bool HeldRegions<D>::holds(const Vec<D>& x) const {
  for (const Zone& zone : zones_)
    if (zone.region->contains(zone.to_rest * x + zone.rest_offset)) return true;
  return false;
}

template class HeldRegions<2>;
template class HeldRegions<3>;

}  // namespace amls
