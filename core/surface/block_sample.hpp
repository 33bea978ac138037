#pragma once
// A sample of the places of a large point set, for measures that would cost
// more than the work they measure if they read every point: the blocks of a
// grid chosen by a hash of their coordinates, one in `every`. The choice
// depends on the places alone, so it is the same for any thread count and
// point order.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
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

  // What a pass has learnt of one block's neighbourhood: which of its 3^D
  // blocks (itself and those across a face, edge or corner; bit
  // sum_a (step_a + 1) 3^a for the steps of -1, 0, 1 along each axis) it has
  // hashed, and which of those are sampled. A pass meets a block's points in
  // runs (a resample writes them in grid order), so a point mostly reads its
  // blocks' answers here instead of hashing up to 2^D blocks.
  struct Neighbourhood {
    IVec<D> block = IVec<D>::Constant(std::numeric_limits<std::int64_t>::min());
    std::uint32_t known = 0;
    std::uint32_t sampled = 0;
  };

  // Where p lies against the sample, within `reach` (at most the side) of its
  // blocks: its own block, or one across a face, edge or corner that is that
  // near; reading and filling `seen` (begun again when p is in another block).
  BlockPlace place(const Vec<D>& p, double reach, Neighbourhood& seen) const {
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
    if (block != seen.block) seen = Neighbourhood{block, 0, 0};
    // The blocks p is near: per axis its own, and the one below or above
    // where p lies within reach of that face.
    const Vec<D> offset = p - side * block.template cast<double>();
    std::uint32_t near_blocks = kAllNeighbours;
    for (int a = 0; a < D; ++a) {
      const unsigned steps = 2u | (offset[a] < reach ? 1u : 0u) | (offset[a] > side - reach ? 4u : 0u);
      near_blocks &= kStepsAlong[a][steps];
    }
    for (std::uint32_t unknown = near_blocks & ~seen.known; unknown != 0; unknown &= unknown - 1) {
      const int bit = std::countr_zero(unknown);
      if (sampled(block + neighbour_step(bit))) seen.sampled |= std::uint32_t{1} << bit;
    }
    seen.known |= near_blocks;
    if (seen.sampled & kOwnBlock) return BlockPlace::inside;
    return (seen.sampled & near_blocks) != 0 ? BlockPlace::near : BlockPlace::away;
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
      Neighbourhood seen;
      for (std::size_t i = begin; i < end; ++i) {
        const BlockPlace place = this->place(positions[i], reach, seen);
        if (place != BlockPlace::away) out.push_back({static_cast<std::uint32_t>(i), place});
      }
    });
    std::vector<Placed> all;
    join_blocks(parts, all, pool);
    return all;
  }

 private:
  static constexpr int kNeighbours = D == 2 ? 9 : 27;  // 3^D
  static constexpr std::uint32_t kAllNeighbours = (std::uint32_t{1} << kNeighbours) - 1;
  static constexpr std::uint32_t kOwnBlock = std::uint32_t{1} << (kNeighbours / 2);  // every step 0

  // The step of a neighbour's bit, digit by digit in base 3.
  static IVec<D> neighbour_step(int bit) {
    IVec<D> step;
    for (int a = 0; a < D; ++a, bit /= 3) step[a] = bit % 3 - 1;
    return step;
  }
  // kStepsAlong[a][s]: the neighbours whose step along axis a is among the
  // set s (bit 0: -1, bit 1: 0, bit 2: +1).
  static constexpr std::array<std::array<std::uint32_t, 8>, D> steps_along() {
    std::array<std::array<std::uint32_t, 8>, D> table{};
    for (int a = 0, weight = 1; a < D; ++a, weight *= 3)
      for (unsigned set = 0; set < 8; ++set)
        for (int bit = 0; bit < kNeighbours; ++bit)
          if (set & (1u << ((bit / weight) % 3))) table[a][set] |= std::uint32_t{1} << bit;
    return table;
  }
  static constexpr std::array<std::array<std::uint32_t, 8>, D> kStepsAlong = steps_along();

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
