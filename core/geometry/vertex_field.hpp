#pragma once
// Sparse storage for per-vertex data near the surface (Update_Function's
// values and the walk's flags). Vertices live in bricks of 4^D; a sparse map
// takes a brick to its index, so memory follows the surface, never the grid's
// volume, and a point's whole neighbourhood of vertices (5 per axis) resolves
// with at most 2^D map lookups instead of one per vertex.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "core/util/flat_hash_map.hpp"
#include "core/geometry/grid.hpp"

namespace amls {

template <int D>
class VertexField {
 public:
  static constexpr int kBrickShift = 2;
  static constexpr std::int64_t kBrickSide = std::int64_t{1} << kBrickShift;
  static constexpr std::uint32_t kBrickVolume = D == 2 ? 16 : 64;

  // The bricks around one box of vertices [lo, lo + 4]^D: vertices in it map
  // to slots by arithmetic alone.
  class Block {
   public:
    std::uint32_t slot(const IVec<D>& v) const {
      int brick = 0;
      for (int a = D - 1; a >= 0; --a) brick = brick * 2 + static_cast<int>((v[a] >> kBrickShift) - base_[a]);
      return bricks_[static_cast<std::size_t>(brick)] * kBrickVolume + local_index(v);
    }
    // The index of brick k of the block, bit a of k being its offset (0 or 1) along axis a.
    std::uint32_t brick(int k) const { return bricks_[static_cast<std::size_t>(k)]; }

   private:
    friend class VertexField;
    IVec<D> base_;                             // brick coordinates of the box's lowest corner
    std::array<std::uint32_t, 1 << D> bricks_{};  // brick index by offset (0 or 1 per axis)
  };

  // The brick holding vertex v.
  static IVec<D> brick_of(const IVec<D>& v) {
    IVec<D> brick;
    for (int a = 0; a < D; ++a) brick[a] = v[a] >> kBrickShift;
    return brick;
  }

  // The place of vertex v in its brick: its slot minus the brick's first.
  static std::uint32_t local_index(const IVec<D>& v) {
    std::uint32_t local = 0;
    for (int a = D - 1; a >= 0; --a)
      local = local * static_cast<std::uint32_t>(kBrickSide) + static_cast<std::uint32_t>(v[a] & (kBrickSide - 1));
    return local;
  }

  void clear() {
    brick_of_.clear();
    brick_origin_.clear();
    recent_.fill(Recent{});
  }

  // The block for the vertex box [lo, lo + 4]^D, creating its bricks if needed.
  Block block(const IVec<D>& lo) {
    Block b;
    b.base_ = brick_of(lo);
    for (int k = 0; k < (1 << D); ++k) {
      IVec<D> brick = b.base_;
      for (int a = 0; a < D; ++a) brick[a] += (k >> a) & 1;
      b.bricks_[static_cast<std::size_t>(k)] = index_of(brick);
    }
    return b;
  }

  // The slot of a vertex, if its brick exists.
  std::optional<std::uint32_t> find(const IVec<D>& v) const {
    const std::uint32_t* index = brick_of_.find(Grid<D>::key(brick_of(v)));
    if (!index) return std::nullopt;
    return *index * kBrickVolume + local_index(v);
  }

  // The slot of the vertex at `offset` (each coordinate in [0, 4)) from the
  // lowest vertex of the brick whose first slot is `first`.
  static std::uint32_t slot_in_brick(std::uint32_t first, const IVec<D>& offset) {
    std::uint32_t local = 0;
    for (int a = D - 1; a >= 0; --a) local = local * static_cast<std::uint32_t>(kBrickSide) + static_cast<std::uint32_t>(offset[a]);
    return first + local;
  }

  // The index of a brick (given by its coordinates, as brick_of's), creating
  // it if needed. The recent bricks, one per residue of the coordinates
  // modulo 4, answer most calls without a map lookup.
  std::uint32_t index_of(const IVec<D>& brick) {
    std::size_t residue = 0;
    for (int a = 0; a < D; ++a) residue = residue * 4 + static_cast<std::size_t>(brick[a] & 3);
    Recent& recent = recent_[residue];
    if (recent.brick == brick) return recent.index;
    auto [index, inserted] = brick_of_.try_emplace(Grid<D>::key(brick));
    if (inserted) {
      *index = static_cast<std::uint32_t>(brick_origin_.size());
      brick_origin_.push_back(brick * kBrickSide);
    }
    recent = {brick, *index};
    return *index;
  }
  // The coordinates of brick `index`.
  IVec<D> brick(std::uint32_t index) const { return brick_of(brick_origin_[index]); }

  // Bricks in use, numbered in creation order, [0, bricks()).
  std::size_t bricks() const { return brick_origin_.size(); }
  // Slots in use: every vertex of every brick, [0, slots()).
  std::size_t slots() const { return brick_origin_.size() * kBrickVolume; }

  IVec<D> vertex_of(std::uint32_t slot) const {
    return brick_origin_[slot / kBrickVolume] + vertex_of_local(slot % kBrickVolume);
  }

  // The offset from its brick's lowest vertex of the vertex with local index `local`.
  static IVec<D> vertex_of_local(std::uint32_t local) {
    IVec<D> v;
    for (int a = 0; a < D; ++a) {
      v[a] = local % static_cast<std::uint32_t>(kBrickSide);
      local /= static_cast<std::uint32_t>(kBrickSide);
    }
    return v;
  }

 private:
  // A brick recently looked up: consecutive blocks share most of their bricks.
  struct Recent {
    IVec<D> brick = IVec<D>::Constant(std::numeric_limits<std::int64_t>::min());  // no brick's coordinates
    std::uint32_t index = 0;
  };

  FlatHashMap<std::uint32_t> brick_of_;
  std::vector<IVec<D>> brick_origin_;  // lowest vertex of each brick
  std::array<Recent, std::size_t{1} << (2 * D)> recent_;
};

}  // namespace amls
