#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/geometry/point_index.hpp"

using namespace amls;

namespace {

// 3000 points in [-0.2, 1.2]^D, then `far` points far outside it (ids from 3000 on).
template <int D>
std::vector<Vec<D>> random_points(std::mt19937& rng, int far) {
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::vector<Vec<D>> pts(3000);
  for (auto& p : pts)
    for (int a = 0; a < D; ++a) p[a] = u(rng);
  for (int k = 0; k < far; ++k) pts.push_back(Vec<D>::Constant(1e4 * (k + 1)));
  return pts;
}

template <int D>
void check_against_brute_force(double cell, double radius, unsigned seed, int far) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  const std::vector<Vec<D>> pts = random_points<D>(rng, far);
  PointIndex<D> index;
  index.build(pts, Vec<D>::Zero(), cell);
  // A far point spreads the box of cells too wide for the dense table.
  REQUIRE(index.uses_dense_table() == (far == 0));
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
  for (const int far : {0, 1}) {
    CAPTURE(far);
    check_against_brute_force<2>(0.05, 0.05, 1, far);
    check_against_brute_force<2>(0.05, 0.13, 2, far);  // radius wider than a cell
    check_against_brute_force<3>(0.1, 0.1, 3, far);
    check_against_brute_force<3>(0.1, 0.04, 4, far);
  }
}

template <int D>
void check_same_order_dense_and_sparse(double cell, unsigned seed) {
  std::mt19937 rng(seed);
  const std::vector<Vec<D>> near = random_points<D>(rng, 0);
  std::vector<Vec<D>> spread = near;
  spread.push_back(Vec<D>::Constant(1e4));
  PointIndex<D> dense, sparse;
  dense.build(near, Vec<D>::Zero(), cell);
  sparse.build(spread, Vec<D>::Zero(), cell);
  REQUIRE(dense.uses_dense_table());
  REQUIRE_FALSE(sparse.uses_dense_table());
  std::uniform_real_distribution<double> u(-0.5, 1.5);  // some queries reach past the points' box
  for (int q = 0; q < 200; ++q) {
    Vec<D> lo;
    for (int a = 0; a < D; ++a) lo[a] = u(rng);
    const Vec<D> hi = lo.array() + 0.1;
    std::vector<std::uint32_t> from_dense, from_sparse;
    dense.gather(lo, hi, cell, from_dense);
    sparse.gather(lo, hi, cell, from_sparse);
    REQUIRE(from_dense == from_sparse);
    const IVec<D> c = dense.cell_of(lo);
    std::vector<std::uint32_t> cells_dense, cells_sparse;
    dense.for_each_in_cells(c.array() - 1, c.array() + 1, [&](std::uint32_t id, const Vec<D>&) { cells_dense.push_back(id); });
    sparse.for_each_in_cells(c.array() - 1, c.array() + 1, [&](std::uint32_t id, const Vec<D>&) { cells_sparse.push_back(id); });
    REQUIRE(cells_dense == cells_sparse);
  }
}

// Results (sums over neighbours) depend on the visiting order, so the two
// cell tables must visit the same points in the same order.
TEST_CASE("the dense and the sparse cell table visit the same points in the same order") {
  check_same_order_dense_and_sparse<2>(0.05, 5);
  check_same_order_dense_and_sparse<3>(0.1, 6);
}

TEST_CASE("the index built on a pool has the same order and the same cells for any thread count") {
  // Enough points for the pooled sort; a far point makes the sparse table.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const bool far : {false, true}) {
    std::vector<Vec<3>> pts(60000);
    for (auto& p : pts) p = Vec<3>(u(rng), u(rng), u(rng));
    if (far) pts[31337] = Vec<3>::Constant(1e3);
    PointIndex<3> serial;
    serial.build(pts, Vec<3>::Zero(), 0.02);
    for (const int threads : {2, 3, 8}) {
      ThreadPool pool(threads);
      PointIndex<3> index;
      // Twice: the second build reuses the first's storage.
      for (int build = 0; build < 2; ++build) {
        index.build(pts, Vec<3>::Zero(), 0.02, pool);
        CHECK(index.uses_dense_table() == !far);
        CHECK(index.order() == serial.order());
        for (const Vec<3>& x : {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.01, 0.99, 0.3), Vec<3>(1e3, 1e3, 1e3)}) {
          std::vector<std::uint32_t> expected, found;
          serial.gather(x, x, 0.05, expected);
          index.gather(x, x, 0.05, found);
          CHECK(found == expected);
        }
      }
    }
  }
}

TEST_CASE("the index rejects non-finite points with a message naming the point") {
  std::vector<Vec<2>> pts{Vec<2>(0, 0), Vec<2>(std::nan(""), 0)};
  PointIndex<2> index;
  CHECK_THROWS_WITH_AS(index.build(pts, Vec<2>::Zero(), 0.1), "point 1 has a non-finite coordinate",
                       std::invalid_argument);
}
