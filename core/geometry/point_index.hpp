#pragma once
// Neighbour queries over a point set (paper, section 3.1, Hash()). Points are
// bucketed by cell in one sorted array (no linked lists); a table takes a cell
// to its run of points. Cells are as wide as the largest query radius, so a
// query inspects at most 3^D cells whatever the grid spacing.
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/util/flat_hash_map.hpp"
#include "core/geometry/grid.hpp"
#include "core/util/thread_pool.hpp"
#include "core/math/vec.hpp"

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
    for_each_run_in_cells(lo, hi, [&](const Run& run) {
      for (std::uint32_t k = run.begin; k < run.end; ++k) fn(ids_[k], positions_[k]);
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
    std::size_t kept = out.size();
    // The cells' runs are collected first and copied a batch at a time, so
    // that `out` grows (and zero-fills) once per batch, not once per cell.
    std::array<Run, kGatherBatch> batch;
    std::size_t batched = 0;
    std::size_t batched_length = 0;
    auto copy_batch = [&] {
      // Room for every id, every id written and only those within reach
      // kept: no branch on the distance, which is hard to predict.
      out.resize(kept + batched_length);
      std::uint32_t* ids = out.data();
      for (std::size_t r = 0; r < batched; ++r)
        for (std::uint32_t k = batch[r].begin; k < batch[r].end; ++k) {
          const Vec<D>& q = positions_[k];
          const Vec<D> outside = (lo - q).cwiseMax(q - hi).cwiseMax(0.0);
          ids[kept] = ids_[k];
          kept += outside.squaredNorm() <= r2 ? 1 : 0;
        }
      batched = batched_length = 0;
    };
    for_each_run_in_cells(cells_->cell_of(lo - Vec<D>::Constant(radius)),
                          cells_->cell_of(hi + Vec<D>::Constant(radius)), [&](const Run& run) {
                            if (batched == batch.size()) copy_batch();
                            batch[batched++] = run;
                            batched_length += run.end - run.begin;
                          });
    copy_batch();
    out.resize(kept);
  }
  // Whether the cell table is the dense array (else the hash map); see below.
  bool uses_dense_table() const { return !dense_.empty(); }

 private:
  // The dense table is used when its box has at most this many cells per
  // point plus kDenseMinCells: at 8 bytes a cell, its memory and the cost of
  // refilling it at every build stay small next to the points' own.
  static constexpr double kDenseCellsPerPoint = 32.0;
  static constexpr double kDenseMinCells = 4096.0;
  // Runs gather() collects before copying their ids: a query of 3^D cells fits.
  static constexpr std::size_t kGatherBatch = 32;

  struct Run {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
  };

  void fill_cell_table(ThreadPool& pool);

  // Calls fn(run) for every non-empty cell in [lo, hi], in for_each_index_in_box's order.
  template <typename Fn>
  void for_each_run_in_cells(const IVec<D>& lo, const IVec<D>& hi, Fn&& fn) const {
    if (dense_.empty()) {
      for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& c) {
        if (const Run* run = runs_.find(Grid<D>::key(c))) fn(*run);
      });
      return;
    }
    // Cells outside the table's box hold no points: clip the query to it, then
    // walk it a row (along axis 0) at a time, in for_each_index_in_box's order.
    const IVec<D> from = lo.cwiseMax(dense_lo_);
    const IVec<D> to = hi.cwiseMin(dense_hi_);
    if (to[0] < from[0]) return;  // (for_each_index_in_box checks the other axes)
    IVec<D> row_end = to;
    row_end[0] = from[0];
    for_each_index_in_box<D>(from, row_end, [&](const IVec<D>& row) {
      const Run* run = &dense_[dense_slot(row)];
      for (std::int64_t x = from[0]; x <= to[0]; ++x, ++run)
        if (run->begin != run->end) fn(*run);
    });
  }

  // The slot of cell c in dense_, which is row-major over [dense_lo_, dense_hi_].
  std::size_t dense_slot(const IVec<D>& c) const {
    std::size_t slot = 0;
    for (int a = D - 1; a >= 0; --a)
      slot = slot * static_cast<std::size_t>(dense_hi_[a] - dense_lo_[a] + 1) +
             static_cast<std::size_t>(c[a] - dense_lo_[a]);
    return slot;
  }

  std::optional<Grid<D>> cells_;
  std::vector<Vec<D>> positions_;  // sorted by cell
  std::vector<std::uint32_t> ids_;  // original index of each sorted position
  // The cell table. Queries are latency-bound on it, so when the points' box
  // of cells is small next to their number it is a dense array over that box
  // (a lookup is one load, and a row of cells is consecutive); otherwise, as
  // for points spread far apart, it is a sparse hash map. Empty dense_ means
  // the map is in use.
  FlatHashMap<Run> runs_;
  std::vector<Run> dense_;
  IVec<D> dense_lo_ = IVec<D>::Zero(), dense_hi_ = IVec<D>::Zero();
  // Each run's cell, kept between builds like keyed_, and the runs each
  // block of the build found.
  std::vector<std::pair<IVec<D>, Run>> cell_runs_;
  std::vector<OwnCacheLine<std::vector<std::pair<IVec<D>, Run>>>> block_runs_;
  // (Morton code of the cell, id) of every point, and the sort's working
  // space: kept so that rebuilding every step does not allocate.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed_, sort_scratch_;
};

extern template class PointIndex<2>;
extern template class PointIndex<3>;

}  // namespace amls
