#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "core/geometry/kd_tree.hpp"

using namespace amls;

namespace {

template <int D>
void check_against_brute_force(double radius, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<Vec<D>> pts(3000);
  for (auto& p : pts)
    for (int a = 0; a < D; ++a) p[a] = u(rng);
  KdTree<D> tree;
  tree.build(pts);
  REQUIRE(tree.size() == pts.size());
  std::vector<std::uint32_t> found;
  for (int q = 0; q < 200; ++q) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = u(rng);
    found.clear();
    tree.gather(x, radius, found);
    std::sort(found.begin(), found.end());
    std::vector<std::uint32_t> expected;
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      if ((pts[i] - x).norm() < radius) expected.push_back(i);
    REQUIRE(found == expected);
  }
}

}  // namespace

TEST_CASE("k-d tree radius queries find exactly the points a brute-force search finds") {
  check_against_brute_force<2>(0.05, 1);
  check_against_brute_force<2>(0.2, 2);
  check_against_brute_force<3>(0.1, 3);
  check_against_brute_force<3>(0.25, 4);
}

TEST_CASE("a rebuilt k-d tree answers for the new points - an empty one finds nothing") {
  KdTree<2> tree;
  std::vector<std::uint32_t> found;
  tree.gather(Vec<2>(0, 0), 1.0, found);
  CHECK(found.empty());
  const std::vector<Vec<2>> first{Vec<2>(0, 0), Vec<2>(1, 0)};
  tree.build(first);
  tree.gather(Vec<2>(0.9, 0), 0.5, found);
  CHECK(found == std::vector<std::uint32_t>{1});
  const std::vector<Vec<2>> second{Vec<2>(5, 5)};
  tree.build(second);
  found.clear();
  tree.gather(Vec<2>(0.9, 0), 0.5, found);
  CHECK(found.empty());
  tree.gather(Vec<2>(5, 5.1), 0.5, found);
  CHECK(found == std::vector<std::uint32_t>{0});
}
