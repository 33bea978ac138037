#include "core/resample/region_rings.hpp"

#include <stdexcept>
#include <string>

namespace amls {

template <int D>
RegionRings<D>::RegionRings(const Grid<D>& cells, const std::vector<IVec<D>>& flagged, std::int64_t most_reach,
                            std::size_t dense_limit)
    : cells_(cells), most_reach_(most_reach) {
  if (flagged.empty()) throw std::invalid_argument("region rings: no flagged cell");
  if (most_reach < 0 || most_reach >= kOutside)
    throw std::logic_error("region rings: a reach of " + std::to_string(most_reach) + " cells does not fit a byte");
  lo_ = hi_ = flagged.front();
  for (const IVec<D>& f : flagged) {
    lo_ = lo_.cwiseMin(f);
    hi_ = hi_.cwiseMax(f);
  }
  box_lo_ = lo_.array() - most_reach;
  double volume = 1.0;  // in double: a box of far-apart cells can overflow an integer
  for (int a = 0; a < D; ++a) {
    size_[static_cast<std::size_t>(a)] = static_cast<std::size_t>(hi_[a] - lo_[a] + 2 * most_reach + 1);
    volume *= static_cast<double>(size_[static_cast<std::size_t>(a)]);
  }
  if (volume <= static_cast<double>(dense_limit)) {
    dense_.assign(static_cast<std::size_t>(volume), kOutside);
    const IVec<D> centre = box_lo_.array() + 1;
    for_each_index_in_box<D>(box_lo_, box_lo_.array() + 2, [&](const IVec<D>& n) {
      if (n != centre)
        steps_.push_back(static_cast<std::ptrdiff_t>(slot(n)) - static_cast<std::ptrdiff_t>(slot(centre)));
    });
  }
  for (const IVec<D>& f : flagged) {
    if (!dense_.empty()) {
      std::uint8_t& r = dense_[slot(f)];
      if (r == kOutside) dense_frontier_.push_back(slot(f));
      r = 0;
    } else if (sparse_.try_emplace(Grid<D>::key(f)).second) {
      sparse_frontier_.push_back(f);  // ring 0: the value a new entry starts with
    }
  }
}

template <int D>
template <typename Cell, typename Grow>
void RegionRings<D>::grow_from(std::vector<Cell>& frontier, std::int64_t reach, Grow&& grow) {
  std::vector<Cell> next;
  for (; reach_ < reach; ++reach_) {
    // A cell first reached from ring r is at Chebyshev distance r + 1: one
    // step to any of the 3^D - 1 neighbours changes each index by at most 1.
    const auto ring = static_cast<std::uint8_t>(reach_ + 1);
    for (const Cell& c : frontier) grow(c, ring, next);
    frontier.swap(next);
    next.clear();
    lo_.array() -= 1;
    hi_.array() += 1;
  }
}

template <int D>
void RegionRings<D>::grow_to(std::int64_t reach) {
  if (reach > most_reach_)
    throw std::logic_error("region rings: " + std::to_string(reach) + " cells beyond the most reach, " +
                           std::to_string(most_reach_));
  // The rings grown from ring r < the most reach stay inside the box of the most reach.
  if (!dense_.empty()) {
    grow_from(dense_frontier_, reach, [&](std::size_t c, std::uint8_t ring, std::vector<std::size_t>& next) {
      for (const std::ptrdiff_t step : steps_) {
        const std::size_t n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(c) + step);
        if (dense_[n] != kOutside) continue;
        dense_[n] = ring;
        next.push_back(n);
      }
    });
  } else {
    grow_from(sparse_frontier_, reach, [&](const IVec<D>& c, std::uint8_t ring, std::vector<IVec<D>>& next) {
      for_each_index_in_box<D>(c.array() - 1, c.array() + 1, [&](const IVec<D>& n) {
        auto [value, inserted] = sparse_.try_emplace(Grid<D>::key(n));
        if (!inserted) return;
        *value = ring;
        next.push_back(n);
      });
    });
  }
}

template <int D>
std::size_t RegionRings<D>::cells_within(std::int64_t ring) const {
  std::size_t n = 0;
  auto count = [&](std::uint8_t r) { n += r <= ring ? 1 : 0; };
  for (const std::uint8_t r : dense_) count(r);
  sparse_.for_each([&](std::uint64_t, const std::uint8_t& r) { count(r); });
  return n;
}

template class RegionRings<2>;
template class RegionRings<3>;

}  // namespace amls
