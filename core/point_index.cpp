#include "core/point_index.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

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
  if (positions.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("too many points for the index: " + std::to_string(positions.size()));
  cells_.emplace(origin, cell_size);

  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec<D>& p = positions[i];
    if (!p.allFinite()) throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
    if (!cells_->contains_with_margin(p, 2))
      throw std::invalid_argument("point " + std::to_string(i) + " lies too far from the grid's origin for its spacing");
    keyed[i] = {morton_code<D>(cells_->cell_of(p)), static_cast<std::uint32_t>(i)};
  }
  // Sorting (code, id) pairs makes the order, and so every query's order, deterministic.
  std::sort(keyed.begin(), keyed.end());

  positions_.resize(keyed.size());
  ids_.resize(keyed.size());
  runs_.clear();
  runs_.reserve(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    ids_[k] = keyed[k].second;
    positions_[k] = positions[keyed[k].second];
    auto [run, inserted] = runs_.try_emplace(Grid<D>::key(cells_->cell_of(positions_[k])));
    if (inserted) run->begin = static_cast<std::uint32_t>(k);
    run->end = static_cast<std::uint32_t>(k + 1);
  }
}

template class PointIndex<2>;
template class PointIndex<3>;

}  // namespace amls
