// The rings of local resampling against the Chebyshev distance to the
// nearest flagged cell, cell by cell, kept in a box or in a hash map.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/resample/region_rings.hpp"

using namespace amls;

namespace {

// Flagged cells in two clusters far apart and a lone cell, grown in two
// steps; every cell of the box around them gets the ring of its Chebyshev
// distance to the nearest flagged cell, or kOutside beyond the reach.
template <int D>
void check_rings(std::size_t dense_limit) {
  const Grid<D> cells(Vec<D>::Constant(-3.0), 0.5);
  std::vector<IVec<D>> flagged;
  for_each_index_in_box<D>(IVec<D>::Constant(-2), IVec<D>::Constant(1), [&](const IVec<D>& c) {
    if ((c.array() + 2).sum() % 3 != 0) flagged.push_back(c);  // a cluster with holes in it
  });
  flagged.push_back(IVec<D>::Constant(20));
  IVec<D> lone = IVec<D>::Zero();
  lone[0] = -15;
  flagged.push_back(lone);
  flagged.push_back(lone);  // twice: one cell all the same
  constexpr std::int64_t kMost = 6;
  RegionRings<D> rings(cells, flagged, kMost, dense_limit);
  auto centre = [&](const IVec<D>& c) {
    return Vec<D>(cells.origin() + (c.template cast<double>().array() + 0.5).matrix() * cells.spacing());
  };
  for (const std::int64_t reach : {std::int64_t{2}, kMost}) {
    rings.grow_to(reach);
    CHECK(rings.reach() == reach);
    std::size_t within_one = 0;
    for_each_index_in_box<D>(IVec<D>::Constant(-25), IVec<D>::Constant(30), [&](const IVec<D>& c) {
      std::int64_t nearest = 1000;
      for (const IVec<D>& f : flagged) nearest = std::min(nearest, (c - f).cwiseAbs().maxCoeff());
      const std::uint8_t expected = nearest <= reach ? static_cast<std::uint8_t>(nearest) : RegionRings<D>::kOutside;
      const std::uint8_t ring = rings.ring(centre(c));
      if (ring != expected)
        FAIL_CHECK("cell " << c.transpose() << ": ring " << int{ring} << ", expected " << int{expected});
      within_one += nearest <= 1 ? 1 : 0;
      // The box of the most reach around the flagged cells' box, [-15, 20] x [-2, 20]^(D - 1).
      IVec<D> lo = IVec<D>::Constant(-2 - kMost);
      lo[0] = -15 - kMost;
      CHECK(rings.may_reach(centre(c)) == ((c.array() >= lo.array()).all() && (c.array() <= 20 + kMost).all()));
    });
    CHECK(rings.cells_within(1) == within_one);
  }
  CHECK_THROWS_AS(rings.grow_to(kMost + 1), std::logic_error);
}

}  // namespace

TEST_CASE(
    "region rings: each cell's ring is its Chebyshev distance to the nearest flagged cell, in a box or a hash map") {
  check_rings<2>(RegionRings<2>::kDenseLimit);
  check_rings<2>(0);
  check_rings<3>(RegionRings<3>::kDenseLimit);
  check_rings<3>(0);
  const Grid<3> cells(Vec<3>::Zero(), 1.0);
  CHECK_THROWS_AS(RegionRings<3>(cells, {}, 3), std::invalid_argument);
  CHECK_THROWS_AS(RegionRings<3>(cells, {IVec<3>::Zero()}, RegionRings<3>::kOutside), std::logic_error);
}
