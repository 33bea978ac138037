#include "core/geometry/point_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace amls {

template <int D>
PointRegion<D>::PointRegion(std::vector<Vec<D>> members, double reach) : members_(std::move(members)), reach_(reach) {
  if (members_.empty()) throw std::invalid_argument("a region needs at least one point");
  if (!(reach > 0.0) || !std::isfinite(reach))
    throw std::invalid_argument("a region's reach must be a finite number > 0, got " + std::to_string(reach));
  Vec<D> sum = Vec<D>::Zero();
  for (std::size_t i = 0; i < members_.size(); ++i) {
    if (!members_[i].allFinite())
      throw std::invalid_argument("region point " + std::to_string(i) + " has a non-finite coordinate");
    sum += members_[i];
  }
  centre_ = sum / static_cast<double>(members_.size());
  for (const Vec<D>& m : members_) extent_ = std::max(extent_, (m - centre_).norm());
  tree_.build(members_);
  try {
    cells_.build(members_, centre_, reach_);
    indexed_ = true;
  } catch (const std::invalid_argument&) {
    // Members too many reaches apart for packed cell keys: the tree answers alone.
  }
}

template <int D>
std::optional<double> PointRegion<D>::near_squared(const Vec<D>& x) const {
  if (!indexed_) return std::nullopt;
  // The cells about x must have keys, with a cell to spare on each side.
  for (int a = 0; a < D; ++a)
    if (!(std::abs((x[a] - centre_[a]) / reach_) + 2.0 < static_cast<double>(Grid<D>::kMaxIndex)))
      return std::nullopt;
  double least = std::numeric_limits<double>::infinity();
  cells_.for_each_within(x, reach_, [&](std::uint32_t, const Vec<D>& m) { least = std::min(least, (m - x).squaredNorm()); });
  return least;
}

template <int D>
bool PointRegion<D>::contains(const Vec<D>& x) const {
  if (const std::optional<double> near = near_squared(x)) return *near <= reach_ * reach_;
  return squared_distance(x) <= reach_ * reach_;
}

template <int D>
double PointRegion<D>::squared_distance(const Vec<D>& x) const {
  if (const std::optional<double> near = near_squared(x); near && *near <= reach_ * reach_) return *near;
  // The tree writes its answer over these; one pair per thread, so that a
  // query allocates nothing once they hold a result.
  thread_local std::vector<std::uint32_t> ids;
  thread_local std::vector<double> squared;
  tree_.nearest(x, 1, ids, squared);
  return squared.front();
}

template <int D>
std::vector<std::uint8_t> PointRegion<D>::mask(std::span<const Vec<D>> positions) const {
  std::vector<std::uint8_t> out(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) out[i] = contains(positions[i]) ? 1 : 0;
  return out;
}

template class PointRegion<2>;
template class PointRegion<3>;

}  // namespace amls
