#include "core/geometry/point_index.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/util/block_join.hpp"
#include "core/util/radix_sort.hpp"

namespace amls {

namespace {

// Spreads the low bits of x so that D - 1 zero bits separate them.
std::uint64_t spread_bits(std::uint64_t x, int d) {
  if (d == 2) {
    x &= 0xffffffffULL;
    x = (x | (x << 16)) & 0x0000ffff0000ffffULL;
    x = (x | (x << 8)) & 0x00ff00ff00ff00ffULL;
    x = (x | (x << 4)) & 0x0f0f0f0f0f0f0f0fULL;
    x = (x | (x << 2)) & 0x3333333333333333ULL;
    x = (x | (x << 1)) & 0x5555555555555555ULL;
  } else {
    x &= 0x1fffffULL;
    x = (x | (x << 32)) & 0x1f00000000ffffULL;
    x = (x | (x << 16)) & 0x1f0000ff0000ffULL;
    x = (x | (x << 8)) & 0x100f00f00f00f00fULL;
    x = (x | (x << 4)) & 0x10c30c30c30c30c3ULL;
    x = (x | (x << 2)) & 0x1249249249249249ULL;
  }
  return x;
}

// The Morton (Z-order) code of a cell: sorting by it keeps cells that are
// close in space close in memory along every axis, not only along x.
template <int D>
std::uint64_t morton_code(const IVec<D>& cell) {
  std::uint64_t code = 0;
  for (int a = 0; a < D; ++a)
    code |= spread_bits(static_cast<std::uint64_t>(cell[a] + Grid<D>::kMaxIndex + 1), D) << a;
  return code;
}

}  // namespace

template <int D>
void PointIndex<D>::build(const std::vector<Vec<D>>& positions, const Vec<D>& origin, double cell_size) {
  ThreadPool serial(1);
  build(positions, origin, cell_size, serial);
}

template <int D>
void PointIndex<D>::build(const std::vector<Vec<D>>& positions, const Vec<D>& origin, double cell_size,
                          ThreadPool& pool) {
  if (positions.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("too many points for the index: " + std::to_string(positions.size()));
  cells_.emplace(origin, cell_size);
  const Grid<D>& cells = *cells_;

  // Each block stops at its first invalid point, and the lowest of those is
  // reported: the same error for any thread count.
  constexpr std::size_t kAllValid = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> first_invalid(static_cast<std::size_t>(pool.threads()), kAllValid);
  keyed_.resize(positions.size());
  pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::size_t& invalid = first_invalid[static_cast<std::size_t>(block)];
    for (std::size_t i = begin; i < end && invalid == kAllValid; ++i) {
      const Vec<D>& p = positions[i];
      if (!p.allFinite() || !cells.contains_with_margin(p, 2)) invalid = i;
      else keyed_[i] = {morton_code<D>(cells.cell_of(p)), static_cast<std::uint32_t>(i)};
    }
  });
  if (const std::size_t i = *std::min_element(first_invalid.begin(), first_invalid.end()); i != kAllValid) {
    throw std::invalid_argument("point " + std::to_string(i) +
                                (positions[i].allFinite() ? " lies too far from the grid's origin for its spacing"
                                                          : " has a non-finite coordinate"));
  }
  // Sorting by code, ids ascending within a code, makes the order, and so
  // every query's order, deterministic.
  radix_sort_by_key(keyed_, sort_scratch_, pool);

  // The points in that order, and a run per cell: each block lists the runs
  // that start in it (a code names one cell, so a run starts where the code
  // changes), and a run ends where the next one starts.
  const std::size_t n = keyed_.size();
  positions_.resize(n);
  ids_.resize(n);
  block_runs_.resize(static_cast<std::size_t>(pool.threads()));
  for (auto& runs : block_runs_) runs.value.clear();
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int block) {
    std::vector<std::pair<IVec<D>, Run>>& runs = block_runs_[static_cast<std::size_t>(block)].value;
    for (std::size_t k = begin; k < end; ++k) {
      ids_[k] = keyed_[k].second;
      positions_[k] = positions[keyed_[k].second];
      if (k == 0 || keyed_[k].first != keyed_[k - 1].first)
        runs.push_back({cells.cell_of(positions_[k]), Run{static_cast<std::uint32_t>(k), 0}});
    }
  });
  join_blocks(block_runs_, cell_runs_, pool);
  for (std::size_t r = 0; r < cell_runs_.size(); ++r)
    cell_runs_[r].second.end = r + 1 < cell_runs_.size() ? cell_runs_[r + 1].second.begin : static_cast<std::uint32_t>(n);
  fill_cell_table(pool);
}

template <int D>
void PointIndex<D>::fill_cell_table(ThreadPool& pool) {
  runs_.clear();
  if (cell_runs_.empty()) {
    dense_.clear();
    return;
  }
  // The box of the cells, per block and then over the blocks.
  std::vector<OwnCacheLine<std::pair<IVec<D>, IVec<D>>>> boxes(
      static_cast<std::size_t>(pool.threads()), {{cell_runs_.front().first, cell_runs_.front().first}});
  pool.parallel_for(cell_runs_.size(), [&](std::size_t begin, std::size_t end, int block) {
    auto& [lo, hi] = boxes[static_cast<std::size_t>(block)].value;
    for (std::size_t r = begin; r < end; ++r) {
      lo = lo.cwiseMin(cell_runs_[r].first);
      hi = hi.cwiseMax(cell_runs_[r].first);
    }
  });
  dense_lo_ = dense_hi_ = cell_runs_.front().first;
  for (const auto& box : boxes) {
    dense_lo_ = dense_lo_.cwiseMin(box.value.first);
    dense_hi_ = dense_hi_.cwiseMax(box.value.second);
  }
  // In floating point: the box of far-flung points can overflow any integer.
  double box_cells = 1.0;
  for (int a = 0; a < D; ++a) box_cells *= static_cast<double>(dense_hi_[a] - dense_lo_[a] + 1);
  if (box_cells <= kDenseCellsPerPoint * static_cast<double>(positions_.size()) + kDenseMinCells) {
    // Tens of megabytes for a million points: emptied and filled on the pool.
    // The table is not cleared between builds, so that resize() constructs
    // (serially) only the cells it adds.
    dense_.resize(static_cast<std::size_t>(box_cells));
    pool.parallel_for(dense_.size(), [&](std::size_t begin, std::size_t end, int) {
      std::fill(dense_.begin() + static_cast<std::ptrdiff_t>(begin), dense_.begin() + static_cast<std::ptrdiff_t>(end),
                Run{});
    });
    pool.parallel_for(cell_runs_.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t r = begin; r < end; ++r) dense_[dense_slot(cell_runs_[r].first)] = cell_runs_[r].second;
    });
  } else {
    dense_.clear();  // (empty: the map is in use)
    for (const auto& [cell, run] : cell_runs_) *runs_.try_emplace(Grid<D>::key(cell)).first = run;
  }
}

template class PointIndex<2>;
template class PointIndex<3>;

}  // namespace amls
