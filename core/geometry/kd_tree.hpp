#pragma once
// A k-d tree over a point set for radius queries: the neighbour index of the
// ray-tracing resampler (Gois et al. 2008), which the paper's grid hash
// replaces. It wraps Debian's nanoflann, kept out of this header so that only
// kd_tree.cpp sees it.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
class KdTree {
 public:
  KdTree();
  ~KdTree();
  KdTree(KdTree&&) noexcept;
  KdTree& operator=(KdTree&&) noexcept;

  // (Re)builds the tree over a copy of `positions`; ids are indices into them.
  void build(std::span<const Vec<D>> positions);
  std::size_t size() const;

  // Appends to `out` the ids of the points p with |p - x| < radius, in the
  // tree's order (fixed for a given build). Allocates only when `out` grows.
  void gather(const Vec<D>& x, double radius, std::vector<std::uint32_t>& out) const;
  // The ids of the `count` points nearest to x (fewer if the tree holds fewer)
  // and their squared distances, nearest first, written over `ids` and `squared`.
  void nearest(const Vec<D>& x, std::size_t count, std::vector<std::uint32_t>& ids, std::vector<double>& squared) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

extern template class KdTree<2>;
extern template class KdTree<3>;

}  // namespace amls
