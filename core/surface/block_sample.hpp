#pragma once
// A sample of the places of a large point set, for measures that would cost
// more than the work they measure if they read every point: the blocks of a
// grid chosen by a hash of their coordinates, one in `every`. The choice
// depends on the places alone, so it is the same for any thread count and
// point order.
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/geometry/grid.hpp"
#include "core/util/block_join.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

// The hash that chooses the blocks: splitmix64's finaliser of the block's key.
inline std::uint64_t block_hash(std::uint64_t key) {
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ULL;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebULL;
  return key ^ (key >> 31);
}

// Where a point lies against a block sample: in a sampled block, within the
// reach of one (and not in one), farther, or where the block grid cannot key
// it (not finite, or too far out).
enum class BlockPlace : std::uint8_t { away, near, inside, unkeyable };

template <int D>
class BlockSample {
 public:
  BlockSample(double side, std::uint64_t every)
      : blocks_(Vec<D>::Zero(), side),
        twos_(std::countr_zero(at_least_one(every))),
        odd_inverse_(odd_inverse(every >> twos_)),
        most_multiple_(~std::uint64_t{0} / every) {}

  double side() const { return blocks_.spacing(); }
  // Whether the block's hash x is a multiple of `every` = 2^t o (o odd):
  // exactly when x o^-1 mod 2^64, rotated right by t, is at most
  // floor((2^64 - 1) / every) (Granlund and Montgomery): a multiplication
  // instead of a 64-bit division, up to 2^D times per point of a pass.
  bool sampled(const IVec<D>& block) const {
    return std::rotr(block_hash(Grid<D>::key(block)) * odd_inverse_, twos_) <= most_multiple_;
  }

  // Where p lies against the sample, within `reach` (at most the side) of its
  // blocks: its own block, or one across a face, edge or corner that is that near.
  BlockPlace place(const Vec<D>& p, double reach) const {
    const double side = this->side();
    IVec<D> block;
    for (int a = 0; a < D; ++a) {
      const double x = p[a] / side;
      // Within the grid's key margin (as Grid::contains_with_margin(p, 2), one block more); NaN fails it too.
      if (!(std::abs(x) + 3.0 < static_cast<double>(Grid<D>::kMaxIndex))) return BlockPlace::unkeyable;
      // floor(x), without std::floor: a library call where SSE4.1 is not assumed.
      const auto truncated = static_cast<std::int64_t>(x);
      block[a] = truncated - (x < static_cast<double>(truncated) ? 1 : 0);
    }
    if (sampled(block)) return BlockPlace::inside;
    const Vec<D> offset = p - side * block.template cast<double>();
    IVec<D> lo = block, hi = block;
    for (int a = 0; a < D; ++a) {
      if (offset[a] < reach) lo[a] -= 1;
      if (offset[a] > side - reach) hi[a] += 1;
    }
    bool near = false;
    for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& b) { near = near || sampled(b); });
    return near ? BlockPlace::near : BlockPlace::away;
  }

  // A point's id and place, for the points a pass keeps.
  struct Placed {
    std::uint32_t id = 0;
    BlockPlace place = BlockPlace::away;
  };

  // The points of `positions` that are not away (in a sampled block, within
  // `reach` of one, or unkeyable; reach 0 keeps only the first and the last),
  // with their places, in ascending id order, on the pool: one light pass
  // over the set.
  std::vector<Placed> placed(const std::vector<Vec<D>>& positions, double reach, ThreadPool& pool) const {
    std::vector<OwnCacheLine<std::vector<Placed>>> parts(static_cast<std::size_t>(pool.threads()));
    pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int block) {
      std::vector<Placed>& out = parts[static_cast<std::size_t>(block)].value;
      for (std::size_t i = begin; i < end; ++i) {
        const BlockPlace place = this->place(positions[i], reach);
        if (place != BlockPlace::away) out.push_back({static_cast<std::uint32_t>(i), place});
      }
    });
    std::vector<Placed> all;
    join_blocks(parts, all, pool);
    return all;
  }

 private:
  static std::uint64_t at_least_one(std::uint64_t every) {
    if (every == 0) throw std::invalid_argument("a block sample takes one block in at least 1, got 0");
    return every;
  }
  // The inverse of an odd number modulo 2^64, by Newton's iteration (each doubles the bits that are right; o o = 1 mod 8).
  static std::uint64_t odd_inverse(std::uint64_t odd) {
    std::uint64_t x = odd;
    for (int i = 0; i < 5; ++i) x *= 2 - odd * x;
    return x;
  }

  Grid<D> blocks_;
  int twos_;                    // every = 2^twos_ odd
  std::uint64_t odd_inverse_;   // odd^-1 mod 2^64
  std::uint64_t most_multiple_;  // floor((2^64 - 1) / every)
};

}  // namespace amls
