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
#include <optional>
#include <span>
#include <vector>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/point_index.hpp"

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
  // Whether a member lies within reach of x. Thread-safe; for a point near
  // the members it looks at a few cells only, not the tree.
  bool contains(const Vec<D>& x) const;
  // 1 for each position within reach of a member, 0 for the others.
  std::vector<std::uint8_t> mask(std::span<const Vec<D>> positions) const;

 private:
  std::vector<Vec<D>> members_;
  double reach_;
  Vec<D> centre_;
  // The squared distance from x to the nearest member when that is at most
  // the reach, infinity when no member is that near; nothing when the cells
  // cannot tell (x, or a member, beyond the reach of their packed keys).
  std::optional<double> near_squared(const Vec<D>& x) const;

  double extent_ = 0.0;
  KdTree<D> tree_;
  // The members in cells as wide as the reach: a member within reach of x
  // lies in the 3^D cells about x, so the questions a region is asked most
  // (is a point on it; how far is a point just outside) need no tree search.
  PointIndex<D> cells_;
  bool indexed_ = false;
};

extern template class PointRegion<2>;
extern template class PointRegion<3>;

}  // namespace amls
