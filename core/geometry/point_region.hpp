#pragma once
// A region of a point-sampled surface, as a user selects it: the positions of
// the points selected (its members), and how far from them a point still
// belongs to it (its reach). Membership is by distance to the members, not by
// the indices of the points selected, so it survives resampling: a point made
// anywhere within reach of a member belongs, whatever its index, and since
// the members never change (a region handle moves them rigidly, as one
// piece), the region neither frays nor spreads from one resample to the next.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/kd_tree.hpp"

namespace amls {

template <int D>
class PointRegion {
 public:
  // Throws std::invalid_argument for no members, a non-finite member, or a
  // reach that is not a finite number > 0.
  PointRegion(std::vector<Vec<D>> members, double reach);

  const std::vector<Vec<D>>& members() const { return members_; }
  double reach() const { return reach_; }
  // The members' mean: the pivot of the region's rotation and scale.
  const Vec<D>& centre() const { return centre_; }
  // The largest distance of a member from the centre.
  double extent() const { return extent_; }

  // The squared distance from x to the nearest member. Thread-safe.
  double squared_distance(const Vec<D>& x) const;
  bool contains(const Vec<D>& x) const { return squared_distance(x) <= reach_ * reach_; }
  // 1 for each position within reach of a member, 0 for the others.
  std::vector<std::uint8_t> mask(std::span<const Vec<D>> positions) const;

 private:
  std::vector<Vec<D>> members_;
  double reach_;
  Vec<D> centre_;
  double extent_ = 0.0;
  KdTree<D> tree_;
};

extern template class PointRegion<2>;
extern template class PointRegion<3>;

}  // namespace amls
