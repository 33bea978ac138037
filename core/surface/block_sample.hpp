#pragma once
// A sample of the places of a large point set, for measures that would cost
// more than the work they measure if they read every point: the blocks of a
// grid chosen by a hash of their coordinates, one in `every`. The choice
// depends on the places alone, so it is the same for any thread count and
// point order.
#include <cstdint>

#include "core/geometry/grid.hpp"

namespace amls {

template <int D>
class BlockSample {
 public:
  BlockSample(double side, std::uint64_t every) : blocks_(Vec<D>::Zero(), side), every_(every) {}

  double side() const { return blocks_.spacing(); }
  // Whether the grid can key p's block (a finite point not too far out).
  bool keyable(const Vec<D>& p) const { return p.allFinite() && blocks_.contains_with_margin(p, 2); }
  bool sampled(const IVec<D>& block) const { return mixed(Grid<D>::key(block)) % every_ == 0; }
  // Whether p's own block is sampled (p keyable).
  bool in_sampled(const Vec<D>& p) const { return sampled(blocks_.cell_of(p)); }
  // Whether p (keyable) lies within `reach` (at most the side) of a sampled
  // block: its own, or one across a face, edge or corner that is that near.
  bool near_sampled(const Vec<D>& p, double reach) const {
    const IVec<D> own = blocks_.cell_of(p);
    if (sampled(own)) return true;
    const Vec<D> offset = p - blocks_.vertex_position(own);
    IVec<D> lo = own, hi = own;
    for (int a = 0; a < D; ++a) {
      if (offset[a] < reach) lo[a] -= 1;
      if (offset[a] > side() - reach) hi[a] += 1;
    }
    bool near = false;
    for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& b) { near = near || sampled(b); });
    return near;
  }

 private:
  static std::uint64_t mixed(std::uint64_t x) {  // splitmix64's finaliser
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }

  Grid<D> blocks_;
  std::uint64_t every_;
};

}  // namespace amls
