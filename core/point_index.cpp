#include "core/point_index.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace amls {

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
    keyed[i] = {Grid<D>::key(cells_->cell_of(p)), static_cast<std::uint32_t>(i)};
  }
  // Sorting (key, id) pairs makes the order, and so every query's order, deterministic.
  std::sort(keyed.begin(), keyed.end());

  positions_.resize(keyed.size());
  ids_.resize(keyed.size());
  runs_.clear();
  runs_.reserve(keyed.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) {
    ids_[k] = keyed[k].second;
    positions_[k] = positions[keyed[k].second];
    auto [run, inserted] = runs_.try_emplace(keyed[k].first);
    if (inserted) run->begin = static_cast<std::uint32_t>(k);
    run->end = static_cast<std::uint32_t>(k + 1);
  }
}

template class PointIndex<2>;
template class PointIndex<3>;

}  // namespace amls
