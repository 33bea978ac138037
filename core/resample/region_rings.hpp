#pragma once
// The rings of local resampling (core/resample/local_resampling.hpp): each
// region cell's Chebyshev distance, in cells, to the nearest flagged cell,
// measured out to a reach that can grow. The local resampler grows it as far
// as the widest support actually present near the region asks, not as far as
// the widest allowed.
//
// The cells within reach are found ring by ring from the flagged cells (a
// breadth-first search over the 3^D - 1 neighbours of each cell, whose steps
// are Chebyshev distances): each cell within reach is visited once, so the
// cost grows with the region and its reach, not with the flagged cells times
// the volume of a box of that reach around each (flagged cells side by side
// share most of their boxes). The rings are kept one byte per cell of the box
// that the most reach can fill, or in a hash map when that box is too large
// (flagged cells far apart).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/geometry/grid.hpp"
#include "core/util/flat_hash_map.hpp"

namespace amls {

template <int D>
class RegionRings {
 public:
  // The ring of a cell beyond the reach measured.
  static constexpr std::uint8_t kOutside = std::numeric_limits<std::uint8_t>::max();
  // The most cells of a box kept one byte per cell (16 MiB).
  static constexpr std::size_t kDenseLimit = std::size_t{1} << 24;

  // The flagged cells (ring 0, at least one) of the region cells `cells`,
  // whose rings can grow out to `most_reach` (below kOutside); kept in a hash
  // map when the box of that reach holds more than `dense_limit` cells.
  RegionRings(const Grid<D>& cells, const std::vector<IVec<D>>& flagged, std::int64_t most_reach,
              std::size_t dense_limit = kDenseLimit);

  // Measures every cell within `reach` (at most the most reach) of a flagged
  // cell; the rings measured so far stay.
  void grow_to(std::int64_t reach);
  std::int64_t reach() const { return reach_; }

  // The ring of the cell holding p; kOutside beyond the reach.
  std::uint8_t ring(const Vec<D>& p) const {
    const IVec<D> c = cells_.cell_of(p);
    if ((c.array() < lo_.array()).any() || (c.array() > hi_.array()).any()) return kOutside;
    if (!dense_.empty()) return dense_[slot(c)];
    const std::uint8_t* ring = sparse_.find(Grid<D>::key(c));
    return ring ? *ring : kOutside;
  }
  // Whether the cell holding p lies in the box of the most reach: beyond
  // it, p's ring stays kOutside however far the rings grow.
  bool may_reach(const Vec<D>& p) const {
    const IVec<D> c = cells_.cell_of(p);
    for (int a = 0; a < D; ++a)
      if (c[a] < box_lo_[a] || c[a] - box_lo_[a] >= static_cast<std::int64_t>(size_[static_cast<std::size_t>(a)]))
        return false;
    return true;
  }
  // How many cells lie within `ring` (at most the reach).
  std::size_t cells_within(std::int64_t ring) const;

 private:
  // Cell c's byte in dense_ (c in the box of the most reach).
  std::size_t slot(const IVec<D>& c) const {
    std::size_t s = 0;
    for (int a = D - 1; a >= 0; --a) s = s * size_[a] + static_cast<std::size_t>(c[a] - box_lo_[a]);
    return s;
  }
  // Grows the rings from `frontier` (the cells of the outermost ring) out to
  // `reach`: `grow(cell, ring, next)` gives each neighbour of the cell
  // without a ring that ring and appends it to `next`.
  template <typename Cell, typename Grow>
  void grow_from(std::vector<Cell>& frontier, std::int64_t reach, Grow&& grow);

  Grid<D> cells_;
  std::int64_t most_reach_;
  IVec<D> lo_, hi_;  // a box holding every cell measured, for a quick rejection
  IVec<D> box_lo_;   // the box of the most reach, and its size along each axis
  std::array<std::size_t, D> size_{};
  std::vector<std::uint8_t> dense_;    // one byte per cell of that box; empty: sparse_
  std::vector<std::ptrdiff_t> steps_;  // the 3^D - 1 neighbours' offsets in dense_
  FlatHashMap<std::uint8_t> sparse_;
  // The cells of the outermost ring: their slots in dense_, or themselves.
  std::vector<std::size_t> dense_frontier_;
  std::vector<IVec<D>> sparse_frontier_;
  std::int64_t reach_ = 0;
};

extern template class RegionRings<2>;
extern template class RegionRings<3>;

}  // namespace amls
