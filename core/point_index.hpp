#pragma once
// Neighbour queries over a point set (paper, section 3.1, Hash()). Points are
// bucketed by cell in one sorted array (no linked lists); a sparse map takes a
// cell to its run of points. Cells are as wide as the largest query radius, so
// a query inspects at most 3^D cells whatever the grid spacing.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/flat_hash_map.hpp"
#include "core/grid.hpp"
#include "core/thread_pool.hpp"
#include "core/vec.hpp"

namespace amls {

template <int D>
class PointIndex {
 public:
  // Buckets `positions` in cells of width `cell_size` anchored at `origin`.
  // Throws std::invalid_argument for non-finite positions or positions too far
  // from the origin for packed cell keys (naming the first such point).
  void build(const std::vector<Vec<D>>& positions, const Vec<D>& origin, double cell_size);
  // The same, computing the cells on `pool`: the same index for any thread count.
  void build(const std::vector<Vec<D>>& positions, const Vec<D>& origin, double cell_size, ThreadPool& pool);

  std::size_t size() const { return ids_.size(); }
  double cell_size() const { return cells_ ? cells_->spacing() : 0.0; }

  // The index cell holding x; cells are `cell_size()` wide.
  IVec<D> cell_of(const Vec<D>& x) const { return cells_->cell_of(x); }

  // Calls fn(id, position) for every point in the cells [lo, hi] (inclusive),
  // in a fixed order (by cell, then by position in the index).
  template <typename Fn>
  void for_each_in_cells(const IVec<D>& lo, const IVec<D>& hi, Fn&& fn) const {
    for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& c) {
      if (const Run* run = runs_.find(Grid<D>::key(c))) {
        for (std::uint32_t k = run->begin; k < run->end; ++k) fn(ids_[k], positions_[k]);
      }
    });
  }

  // Calls fn(id, position) for every indexed point p with |p - x| <= radius,
  // in the order of for_each_in_cells.
  template <typename Fn>
  void for_each_within(const Vec<D>& x, double radius, Fn&& fn) const {
    if (!cells_) return;
    const double r2 = radius * radius;
    for_each_in_cells(cells_->cell_of(x - Vec<D>::Constant(radius)), cells_->cell_of(x + Vec<D>::Constant(radius)),
                      [&](std::uint32_t id, const Vec<D>& q) {
                        if ((q - x).squaredNorm() <= r2) fn(id, q);
                      });
  }

  // The index's order: position k of the cell-sorted arrays holds point
  // order()[k]. A caller that reorders its points by it and then calls
  // renumber_in_cell_order() gets ids equal to positions in cell order, so
  // that neighbours are close in memory.
  const std::vector<std::uint32_t>& order() const { return ids_; }
  void renumber_in_cell_order() {
    for (std::uint32_t k = 0; k < ids_.size(); ++k) ids_[k] = k;
  }

  // The ids of the points within `radius` of the box [lo, hi] (a point when
  // lo = hi), appended to `out` in the order of for_each_in_cells.
  void gather(const Vec<D>& lo, const Vec<D>& hi, double radius, std::vector<std::uint32_t>& out) const {
    if (!cells_) return;
    const double r2 = radius * radius;
    for_each_in_cells(cells_->cell_of(lo - Vec<D>::Constant(radius)), cells_->cell_of(hi + Vec<D>::Constant(radius)),
                      [&](std::uint32_t id, const Vec<D>& q) {
                        const Vec<D> outside = (lo - q).cwiseMax(q - hi).cwiseMax(0.0);
                        if (outside.squaredNorm() <= r2) out.push_back(id);
                      });
  }

 private:
  struct Run {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
  };

  std::optional<Grid<D>> cells_;
  std::vector<Vec<D>> positions_;  // sorted by cell
  std::vector<std::uint32_t> ids_;  // original index of each sorted position
  FlatHashMap<Run> runs_;
  // (Morton code of the cell, id) of every point, and the sort's working
  // space: kept so that rebuilding every step does not allocate.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed_, sort_scratch_;
};

extern template class PointIndex<2>;
extern template class PointIndex<3>;

}  // namespace amls
