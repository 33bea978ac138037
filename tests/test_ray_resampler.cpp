#include <doctest/doctest.h>

#include <algorithm>

#include "core/deform/flow_deformation.hpp"
#include "core/resample/ray_resampler.hpp"
#include "core/run/ray_tracing_surface.hpp"
#include "core/geometry/shapes.hpp"
#include "resampling_checks.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::ready_surface;

namespace {

template <int D>
double closest_pair(const std::vector<Vec<D>>& p) {
  const auto nn = amls::test::nearest_neighbour_distances<D>(p);
  return *std::min_element(nn.begin(), nn.end());
}

}  // namespace

TEST_CASE("ray resampling of a circle puts every point on F = 0, with no gap wider than 2 h") {
  ThreadPool pool(2);
  const auto surface = test::circle_surface(pool);
  RayResampler<2> resampler;
  const PointSet<2> out = resampler.resample(surface, pool);
  test::check_resampled_circle(surface, out);
  CHECK(closest_pair<2>(out.positions) >= 0.5 * surface.grid().spacing());
  CHECK(resampler.stats().removed > 0);  // crossings of horizontal and vertical rays do cluster
  CHECK(resampler.stats().inserted == out.size());
}

TEST_CASE("ray resampling of a sphere puts every point on it, with no hole") {
  ThreadPool pool(2);
  const auto surface = test::sphere_surface(pool);
  RayResampler<3> resampler;
  const PointSet<3> out = resampler.resample(surface, pool);
  test::check_resampled_sphere(surface, out);
  CHECK(closest_pair<3>(out.positions) >= 0.5 * surface.grid().spacing());
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
  // F is exactly 0 at the line's vertices, which count as positive, so each
  // vertical ray has one sign change, ending at the vertex; the horizontal ray
  // on the line itself sees no sign change.
  ThreadPool pool(1);
  const auto surface = test::line_through_vertices(pool);
  RayResampler<2> resampler;
  test::check_one_point_per_vertex(resampler.resample(surface, pool), surface.grid().spacing());
  CHECK(resampler.stats().removed == 0);
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

TEST_CASE("a ray-tracing step without resampling only deforms the points") {
  const Grid<2> grid = Grid<2>::unit(64);
  RayTracingSurface<2> surface(grid, AmlsParameters{}, RaySettings{}, 1);
  surface.set_points(sample_circle(Vec<2>(0.5, 0.5), 0.2, 100));
  const FlowDeformation<2> shift(std::make_shared<RigidRotation<2>>(Vec<2>(0.5, 0.5), 1.0), 1);
  const RayStepStats stats = surface.step(shift, 0.0, 0.1, false);
  CHECK(stats.points_after == 100);
  CHECK(stats.resample.crossings == 0);
  CHECK(stats.timings.intersections == 0.0);
  CHECK(surface.points().positions.front() != sample_circle(Vec<2>(0.5, 0.5), 0.2, 100).positions.front());
  const RayStepStats resampled = surface.step(shift, 0.1, 0.2);
  CHECK(resampled.resample.crossings > 0);
}

TEST_CASE("ray-tracing settings are checked") {
  CHECK_THROWS_AS(RayResampler<2>(RaySettings{0, 0.5}), std::invalid_argument);
  CHECK_THROWS_AS(RayResampler<2>(RaySettings{2, -1.0}), std::invalid_argument);
}
