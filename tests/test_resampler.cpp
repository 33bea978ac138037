#include <doctest/doctest.h>

#include <algorithm>

#include "core/metrics.hpp"
#include "core/resampler.hpp"
#include "core/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::nearest_neighbour_distances;
using amls::test::ready_surface;
using amls::test::widest_circle_gap;

namespace {

template <int D>
PointSet<D> resample_once(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  Resampler<D> resampler;
  resampler.update_function(surface, pool);
  return resampler.resample(surface, variant, pool);
}

}  // namespace

TEST_CASE("exact resampling of a circle puts every new point on F = 0, well spaced, with no gap wider than 2 h") {
  ThreadPool pool(2);
  const Grid<2> grid = Grid<2>::unit(128);
  const double h = grid.spacing();
  const Vec<2> center(0.5, 0.75);
  const auto surface = ready_surface(sample_circle(center, 0.15, 150), grid, pool);
  const PointSet<2> out = resample_once(surface, Variant::exact, pool);

  REQUIRE(out.size() > 100);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Evaluation<2> e = surface.evaluate(out.positions[i]);
    REQUIRE(e.defined);
    CHECK(std::abs(e.value) < 1e-12);
    CHECK(std::abs((out.positions[i] - center).norm() - 0.15) < 1e-10);  // the circle is reproduced exactly
    CHECK(out.normals[i].dot((out.positions[i] - center).normalized()) > 0.999999);
  }
  const auto nn = nearest_neighbour_distances<2>(out.positions);
  CHECK(*std::min_element(nn.begin(), nn.end()) > 0.25 * h);
  CHECK(*std::max_element(nn.begin(), nn.end()) < 2.0 * h);
  CHECK(widest_circle_gap(out.positions, center, 0.15) < 2.0 * h);  // as for the ray tracer
}

TEST_CASE("exact resampling of a sphere puts every new point on the sphere, well spaced, with no hole") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> center(0.35, 0.35, 0.35);
  const auto surface = ready_surface(sample_sphere(center, 0.15, 3000), grid, pool);
  const PointSet<3> out = resample_once(surface, Variant::exact, pool);
  REQUIRE(out.size() > 800);
  double worst = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) worst = std::max(worst, std::abs((out.positions[i] - center).norm() - 0.15));
  CHECK(worst < 1e-9);
  // No hole: every place on the sphere lies within 1.25 h of a new point (as for the ray tracer).
  const PointSet<3> probes = sample_sphere(center, 0.15, 20000);
  CHECK(nearest_distance_stats<3>(probes.positions, out.positions, h).max < 1.25);
  const auto nn = nearest_neighbour_distances<3>(out.positions);
  CHECK(*std::min_element(nn.begin(), nn.end()) > 0.25 * h);
  CHECK(*std::max_element(nn.begin(), nn.end()) < 2.0 * h);
}

TEST_CASE("interpolated resampling stays within a small fraction of h of a circle") {
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  const Vec<2> center(0.5, 0.75);
  const auto surface = ready_surface(sample_circle(center, 0.15, 150), grid, pool);
  const PointSet<2> out = resample_once(surface, Variant::interpolated, pool);
  REQUIRE(out.size() > 100);
  for (const auto& q : out.positions) CHECK(std::abs((q - center).norm() - 0.15) < 0.05 * grid.spacing());
}

TEST_CASE("resampling gives the same points for any thread count") {
  const Grid<2> grid = Grid<2>::unit(128);
  ThreadPool one(1), three(3);
  const auto a = resample_once(ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.2, 97), grid, one), Variant::exact, one);
  const auto b = resample_once(ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.2, 97), grid, three), Variant::exact, three);
  CHECK(a.positions == b.positions);
  CHECK(a.normals == b.normals);
}

TEST_CASE("a surface through grid vertices gives exactly one point per vertex") {
  // The line y = 0.5 lies on a grid line of the 16-cell grid: F is exactly 0
  // there. A zero counts as positive, so each vertex on the line is the upper
  // end of one crossing edge (from the negative vertex below) and gets one point.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(16);
  PointSet<2> line;
  for (int i = 0; i <= 40; ++i) line.add(Vec<2>(0.25 + 0.0125 * i, 0.5), Vec<2>(0, 1));
  const auto surface = ready_surface(std::move(line), grid, pool);
  const PointSet<2> out = resample_once(surface, Variant::exact, pool);
  REQUIRE(!out.empty());
  std::vector<double> xs;
  for (const auto& q : out.positions) {
    CHECK(q.y() == 0.5);
    const double k = q.x() / grid.spacing();
    CHECK(k == std::round(k));  // on a vertex
    xs.push_back(q.x());
  }
  std::sort(xs.begin(), xs.end());
  CHECK(std::adjacent_find(xs.begin(), xs.end()) == xs.end());
}
