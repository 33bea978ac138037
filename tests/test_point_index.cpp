#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "core/point_index.hpp"

using namespace amls;

namespace {

template <int D>
void check_against_brute_force(double cell, double radius, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<Vec<D>> pts(3000);
  for (auto& p : pts)
    for (int a = 0; a < D; ++a) p[a] = u(rng);
  PointIndex<D> index;
  index.build(pts, Vec<D>::Zero(), cell);
  std::uniform_real_distribution<double> extent(0.0, 0.15);
  for (int q = 0; q < 400; ++q) {
    // Even queries are points, odd ones boxes.
    Vec<D> lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[a] = u(rng);
      hi[a] = lo[a] + (q % 2 ? extent(rng) : 0.0);
    }
    std::vector<std::uint32_t> found;
    index.gather(lo, hi, radius, found);
    std::sort(found.begin(), found.end());
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < pts.size(); ++i) {
      const Vec<D> nearest = pts[i].cwiseMax(lo).cwiseMin(hi);  // the box's point nearest to it
      if ((pts[i] - nearest).norm() <= radius) expected.push_back(i);
    }
    REQUIRE(found == expected);
  }
}

}  // namespace

TEST_CASE("neighbour queries around points and boxes find exactly the points a brute-force search finds") {
  check_against_brute_force<2>(0.05, 0.05, 1);
  check_against_brute_force<2>(0.05, 0.13, 2);  // radius wider than a cell
  check_against_brute_force<3>(0.1, 0.1, 3);
  check_against_brute_force<3>(0.1, 0.04, 4);
}

TEST_CASE("the index rejects non-finite points with a message naming the point") {
  std::vector<Vec<2>> pts{Vec<2>(0, 0), Vec<2>(std::nan(""), 0)};
  PointIndex<2> index;
  CHECK_THROWS_WITH_AS(index.build(pts, Vec<2>::Zero(), 0.1), "point 1 has a non-finite coordinate",
                       std::invalid_argument);
}
