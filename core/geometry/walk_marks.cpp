#include "core/geometry/walk_marks.hpp"

#include <array>
#include <limits>

namespace amls {

namespace {

// The walk's box around a point in cell I: vertices [I + kWalkLow, I + kWalkHigh]^D.
constexpr std::int64_t kWalkLow = -1;
constexpr std::int64_t kWalkHigh = 2;

// The walk's vertices as bits of the 2^D bricks its box spans: of[o][k] has
// bit l set when the vertex with local index l of brick k of the block (see
// VertexField::Block::brick) is in the walk of a point whose box's lowest
// vertex has local index o. Marking a point is then 2^D ORs.
template <int D>
struct WalkMasks {
  using Mask = typename WalkMarks<D>::Mask;
  std::array<std::array<Mask, 1 << D>, VertexField<D>::kBrickVolume> of{};

  WalkMasks() {
    for (std::uint32_t o = 0; o < VertexField<D>::kBrickVolume; ++o) {
      const IVec<D> lo = VertexField<D>::vertex_of_local(o);
      const IVec<D> hi = lo.array() + (kWalkHigh - kWalkLow);
      for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& v) {
        if (((v.array() == lo.array()) || (v.array() == hi.array())).count() >= 2) return;  // on a corner or edge of the box (see resampler.hpp)
        int brick = 0;
        for (int a = D - 1; a >= 0; --a) brick = brick * 2 + static_cast<int>(v[a] >> VertexField<D>::kBrickShift);
        of[o][static_cast<std::size_t>(brick)] |= static_cast<Mask>(Mask{1} << VertexField<D>::local_index(v));
      });
    }
  }
};

// Marks the walks of positions [begin, end) in `field` and `needed` (brick index -> mask).
template <int D>
void mark_range(const Grid<D>& grid, const std::vector<Vec<D>>& positions, std::size_t begin, std::size_t end,
                VertexField<D>& field, std::vector<typename WalkMarks<D>::Mask>& needed) {
  static const WalkMasks<D> walk;
  // Consecutive points often share their cell (nothing new to mark) or their
  // block of bricks (no new lookups).
  IVec<D> previous_cell = IVec<D>::Constant(std::numeric_limits<std::int64_t>::min());
  IVec<D> block_base = previous_cell;
  typename VertexField<D>::Block bricks_around;
  for (std::size_t i = begin; i < end; ++i) {
    const IVec<D> cell = grid.cell_of(positions[i]);
    if (cell == previous_cell) continue;
    previous_cell = cell;
    const IVec<D> lo = cell.array() + kWalkLow;
    if (VertexField<D>::brick_of(lo) != block_base) {
      bricks_around = field.block(lo);
      block_base = VertexField<D>::brick_of(lo);
      needed.resize(field.bricks(), 0);
    }
    const auto& masks = walk.of[VertexField<D>::local_index(lo)];
    for (int k = 0; k < (1 << D); ++k) needed[bricks_around.brick(k)] |= masks[static_cast<std::size_t>(k)];
  }
}

}  // namespace

template <int D>
void WalkMarks<D>::mark(const Grid<D>& grid, const std::vector<Vec<D>>& positions, VertexField<D>& field,
                        ThreadPool& pool) {
  needed_.clear();
  parts_.resize(static_cast<std::size_t>(pool.threads() - 1));
  for (Part& part : parts_) {
    part.field.clear();
    part.needed.clear();
  }
  pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int block) {
    if (block == 0) {
      mark_range(grid, positions, begin, end, field, needed_);
    } else {
      Part& part = parts_[static_cast<std::size_t>(block - 1)];
      mark_range(grid, positions, begin, end, part.field, part.needed);
    }
  });
  // A block's bricks in its order of first appearance: those new to the
  // blocks before it are numbered next, as a serial pass would number them.
  for (const Part& part : parts_) {
    for (std::uint32_t b = 0; b < part.field.bricks(); ++b) {
      const std::uint32_t index = field.index_of(part.field.brick(b));
      if (index == needed_.size()) needed_.push_back(0);
      needed_[index] |= part.needed[b];
    }
  }
}

template class WalkMarks<2>;
template class WalkMarks<3>;

}  // namespace amls
