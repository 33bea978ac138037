#pragma once
// How a resample's new points join the old ones that stay: local resampling
// (core/resample/local_resampling.hpp) replaces only the old points of the
// region R it resampled, and any resample keeps the points that region
// handles hold (core/geometry/held_regions.hpp) as they are.
//
// A kept point next to new ones claims its nearest grid vertex: a new point
// whose nearest vertex is claimed counts as HAVECLOSEPOINT there and is
// dropped, as is one closer to a kept point than the closest two new points
// of R are to each other, h / sqrt(2) at most (a kept point off the grid can
// be that close to a crossing whose nearest vertex it does not claim). A new
// point within a held region is dropped too where a kept point lies within
// 1.5 h: the region's own points are there (farther, it fills a hole).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/geometry/grid.hpp"
#include "core/geometry/held_regions.hpp"
#include "core/geometry/point_set.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

// Where the old and new points lie against R, in rings of region cells
// (core/resample/region_rings.hpp): R is the rings up to `region`, the strip
// walked around it those up to `walked`.
struct SpliceRings {
  std::span<const std::uint8_t> old_ring;    // one per old point; empty: every point in R (a whole resample)
  std::span<const std::uint8_t> fresh_ring;  // one per new point; empty: likewise
  std::uint8_t region = 0;
  std::uint8_t walked = 0;
  // Whether the new points of the strip (beyond R, within the walked rings)
  // are kept where they fill the seam (LocalResampleOptions::fill_seam).
  bool fill = false;
};

struct SpliceCounts {
  std::size_t replaced = 0;         // old points of R removed
  std::size_t held = 0;             // old points of R kept because a region holds them
  std::size_t inserted = 0;         // new points of R kept
  std::size_t filled_at_seam = 0;   // new points of the strip kept
  std::size_t dropped_at_seam = 0;  // new points dropped for a kept point's vertex or nearness
  std::size_t covered = 0;          // new points dropped within a held region
};

// Replaces the old points of R by the new ones (and those of the strip where
// they fill the seam), keeping the held ones. `strain`, if given, holds one
// value per old point and follows them; new points start at 0. Kept points
// come first, in their order, then the new ones, in theirs.
template <int D>
SpliceCounts splice_points(PointSet<D>& points, std::vector<float>* strain, const PointSet<D>& fresh,
                           const SpliceRings& rings, const HeldRegions<D>& held, const Grid<D>& grid, ThreadPool& pool);

extern template SpliceCounts splice_points<2>(PointSet<2>&, std::vector<float>*, const PointSet<2>&, const SpliceRings&,
                                              const HeldRegions<2>&, const Grid<2>&, ThreadPool&);
extern template SpliceCounts splice_points<3>(PointSet<3>&, std::vector<float>*, const PointSet<3>&, const SpliceRings&,
                                              const HeldRegions<3>&, const Grid<3>&, ThreadPool&);

}  // namespace amls
