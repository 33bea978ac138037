#pragma once
// Update_Function's first pass: which vertices the walk reads. The walk around
// a point in cell I covers the vertices [I - 1, I + 2]^D but those on the
// box's corners and edges (see core/resample/resampler.hpp); they are marked as bits of
// their bricks.
//
// The points are split in contiguous blocks marked in parallel, each block
// creating its bricks in a field of its own; the blocks' fields are then
// merged in block order. A brick thus gets the number it gets from one serial
// pass over the points (the order of first appearance), for any thread count.
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/geometry/grid.hpp"
#include "core/util/thread_pool.hpp"
#include "core/geometry/vertex_field.hpp"

namespace amls {

template <int D>
class WalkMarks {
 public:
  // One bit per vertex of a brick, by local index (VertexField::local_index).
  using Mask = std::conditional_t<D == 2, std::uint16_t, std::uint64_t>;

  // Marks the walks of `positions` (in cell order, so that consecutive points
  // share bricks), creating their bricks in `field`, which must be empty.
  void mark(const Grid<D>& grid, const std::vector<Vec<D>>& positions, VertexField<D>& field, ThreadPool& pool);

  // Brick index -> the vertices of that brick the walk reads.
  const std::vector<Mask>& needed() const { return needed_; }

 private:
  // The bricks and marks of one block beyond the first (which works on the
  // caller's field directly).
  struct Part {
    VertexField<D> field;
    std::vector<Mask> needed;
  };

  std::vector<Mask> needed_;
  std::vector<Part> parts_;  // kept between calls, so that their storage is reused
};

extern template class WalkMarks<2>;
extern template class WalkMarks<3>;

}  // namespace amls
