#include <doctest/doctest.h>

#include <algorithm>

#include "core/metrics.hpp"
#include "core/ray_resampler.hpp"
#include "core/ray_tracing_surface.hpp"
#include "core/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::ready_surface;
using amls::test::widest_circle_gap;

namespace {

template <int D>
double closest_pair(const std::vector<Vec<D>>& p) {
  const auto nn = amls::test::nearest_neighbour_distances<D>(p);
  return *std::min_element(nn.begin(), nn.end());
}

}  // namespace

// The gap bounds are the grid walk's (tests/test_resampler.cpp): clusters merged
// within h/2 can leave h/2 + the widest gap between crossings + h/2 between kept points.
TEST_CASE("ray resampling of a circle puts every point on F = 0, with no gap wider than 2 h") {
  ThreadPool pool(2);
  const Grid<2> grid = Grid<2>::unit(128);
  const double h = grid.spacing();
  const Vec<2> center(0.5, 0.75);
  const auto surface = ready_surface(sample_circle(center, 0.15, 150), grid, pool);
  RayResampler<2> resampler;
  const PointSet<2> out = resampler.resample(surface, pool);

  REQUIRE(out.size() > 100);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Evaluation<2> e = surface.evaluate(out.positions[i]);
    REQUIRE(e.defined);
    CHECK(std::abs(e.value) < 1e-12);
    CHECK(std::abs((out.positions[i] - center).norm() - 0.15) < 1e-10);  // the circle is reproduced exactly
    CHECK(out.normals[i].dot((out.positions[i] - center).normalized()) > 0.999999);
  }
  CHECK(widest_circle_gap(out.positions, center, 0.15) < 2.0 * h);
  CHECK(closest_pair<2>(out.positions) >= 0.5 * h);
  CHECK(resampler.stats().removed > 0);  // crossings of horizontal and vertical rays do cluster
  CHECK(resampler.stats().inserted == out.size());
}

TEST_CASE("ray resampling of a sphere puts every point on it, with no hole") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> center(0.35, 0.35, 0.35);
  const auto surface = ready_surface(sample_sphere(center, 0.15, 3000), grid, pool);
  RayResampler<3> resampler;
  const PointSet<3> out = resampler.resample(surface, pool);
  REQUIRE(out.size() > 800);
  double worst = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) worst = std::max(worst, std::abs((out.positions[i] - center).norm() - 0.15));
  CHECK(worst < 1e-9);
  // Every place on the sphere lies within 1.25 h of a new point.
  const PointSet<3> probes = sample_sphere(center, 0.15, 20000);
  CHECK(nearest_distance_stats<3>(probes.positions, out.positions, h).max < 1.25);
  CHECK(closest_pair<3>(out.positions) >= 0.5 * h);
}

TEST_CASE("cluster removal leaves no pair closer than its threshold, and every removed candidate near a kept one") {
  ThreadPool pool(3);
  const Grid<2> grid = Grid<2>::unit(64);
  const double h = grid.spacing();
  const auto surface = ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.3, 200), grid, pool);
  for (const double threshold : {0.5, 1.0, 1.7}) {
    RayResampler<2> resampler(RaySettings{2, threshold});
    const PointSet<2> out = resampler.resample(surface, pool);
    REQUIRE(out.size() > 10);
    CHECK(closest_pair<2>(out.positions) >= threshold * h);
    const auto& candidates = resampler.candidates().positions;
    CHECK(resampler.stats().removed + out.size() == candidates.size());
    for (const Vec<2>& c : candidates) {
      double nearest = 1e300;
      for (const Vec<2>& q : out.positions) nearest = std::min(nearest, (q - c).norm());
      CHECK(nearest < threshold * h);
    }
  }
}

TEST_CASE("ray resampling gives the same points for any thread count") {
  const Grid<3> grid = Grid<3>::unit(32);
  ThreadPool one(1), three(3);
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.45, 0.5, 0.52), 0.2, 1500);
  RayResampler<3> a, b;
  const PointSet<3> pa = a.resample(ready_surface(sphere, grid, one), one);
  const PointSet<3> pb = b.resample(ready_surface(sphere, grid, three), three);
  REQUIRE(pa.size() > 100);
  CHECK(pa.positions == pb.positions);
  CHECK(pa.normals == pb.normals);
}

TEST_CASE("a surface through grid vertices gives one ray-traced point per crossing line, at the vertex") {
  // y = 0.5 lies on a grid line: F is exactly 0 at its vertices, which count as
  // positive, so each vertical ray has one sign change, ending at the vertex;
  // the horizontal ray on the line itself sees no sign change.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(16);
  PointSet<2> line;
  for (int i = 0; i <= 40; ++i) line.add(Vec<2>(0.25 + 0.0125 * i, 0.5), Vec<2>(0, 1));
  const auto surface = ready_surface(std::move(line), grid, pool);
  RayResampler<2> resampler;
  const PointSet<2> out = resampler.resample(surface, pool);
  REQUIRE(!out.empty());
  CHECK(resampler.stats().removed == 0);
  std::vector<double> xs;
  for (const auto& q : out.positions) {
    CHECK(q.y() == 0.5);
    const double k = q.x() / grid.spacing();
    CHECK(k == std::round(k));
    xs.push_back(q.x());
  }
  std::sort(xs.begin(), xs.end());
  CHECK(std::adjacent_find(xs.begin(), xs.end()) == xs.end());
}

TEST_CASE("the ray-tracing loop's pseudo-normals (k-d tree neighbours) are AmlsSurface's (grid hash)") {
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  // An ellipse-like, unevenly sampled curve: the fits differ from point to point.
  PointSet<2> points;
  for (int i = 0; i < 300; ++i) {
    const double t = 2.0 * std::numbers::pi * (i + 0.3 * std::sin(7.0 * i)) / 300.0;
    const Vec<2> n(std::cos(t) / 0.2, std::sin(t) / 0.12);
    points.add(Vec<2>(0.5 + 0.2 * std::cos(t), 0.5 + 0.12 * std::sin(t)), n.normalized());
  }
  RayTracingSurface<2> ray(grid, AmlsParameters{}, RaySettings{}, 2);
  ray.set_points(points);
  const NormalStats stats = ray.refresh_normals();
  CHECK(stats.failed() == 0);
  // AmlsSurface reorders its points by cell: match them by position.
  const auto surface = ready_surface(points, grid, pool);
  for (std::size_t i = 0; i < surface.points().size(); ++i) {
    const auto it = std::find(points.positions.begin(), points.positions.end(), surface.points().positions[i]);
    REQUIRE(it != points.positions.end());
    const auto j = static_cast<std::size_t>(it - points.positions.begin());
    CHECK((ray.pseudo_normals()[j] - surface.pseudo_normals()[i]).norm() < 1e-12);
  }
}

TEST_CASE("ray-tracing settings are checked") {
  CHECK_THROWS_AS(RayResampler<2>(RaySettings{0, 0.5}), std::invalid_argument);
  CHECK_THROWS_AS(RayResampler<2>(RaySettings{2, -1.0}), std::invalid_argument);
}
