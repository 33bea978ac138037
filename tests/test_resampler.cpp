#include <doctest/doctest.h>

#include <algorithm>

#include "core/resampler.hpp"
#include "core/shapes.hpp"
#include "resampling_checks.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::nearest_neighbour_distances;
using amls::test::ready_surface;

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
  const auto surface = test::circle_surface(pool);
  const double h = surface.grid().spacing();
  const PointSet<2> out = resample_once(surface, Variant::exact, pool);
  test::check_resampled_circle(surface, out);
  const auto nn = nearest_neighbour_distances<2>(out.positions);
  CHECK(*std::min_element(nn.begin(), nn.end()) > 0.25 * h);
  CHECK(*std::max_element(nn.begin(), nn.end()) < 2.0 * h);
}

TEST_CASE("HAVECLOSEPOINT keeps the crossing nearest each vertex: spacings right after a resample lie in [0.5 h, 1.5 h]") {
  // Circles of many radii and sub-cell offsets meet the grid's vertices at
  // every angle; the walk-order rule of the paper left gaps up to 1.6 h here.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(64);
  const double h = grid.spacing();
  double smallest = 1e300;
  double largest = 0.0;
  for (int k = 0; k < 12; ++k) {
    const Vec<2> center(0.5 + 0.37 * h * k / 12.0, 0.5 + 0.71 * h * ((k * 5) % 12) / 12.0);
    const double radius = 0.12 + 0.02 * k;
    const auto surface = ready_surface(sample_circle(center, radius, 400), grid, pool);
    const auto nn = nearest_neighbour_distances<2>(resample_once(surface, Variant::exact, pool).positions);
    smallest = std::min(smallest, *std::min_element(nn.begin(), nn.end()));
    largest = std::max(largest, *std::max_element(nn.begin(), nn.end()));
  }
  CHECK(smallest >= 0.5 * h);
  CHECK(largest <= 1.5 * h);
}

TEST_CASE("exact resampling of a sphere puts every new point on the sphere, well spaced, with no hole") {
  ThreadPool pool(2);
  const auto surface = test::sphere_surface(pool);
  const double h = surface.grid().spacing();
  const PointSet<3> out = resample_once(surface, Variant::exact, pool);
  test::check_resampled_sphere(surface, out);
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
  // F is exactly 0 at the line's vertices. A zero counts as positive, so each
  // vertex on the line is the upper end of one crossing edge (from the negative
  // vertex below) and gets one point.
  ThreadPool pool(1);
  const auto surface = test::line_through_vertices(pool);
  test::check_one_point_per_vertex(resample_once(surface, Variant::exact, pool), surface.grid().spacing());
}

TEST_CASE("memory follows the surface: a small sphere on a 2048^3 grid touches few vertices") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(2048);
  const auto surface = ready_surface(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.01, 5000), grid, pool);
  Resampler<3> resampler;
  resampler.update_function(surface, pool);
  const PointSet<3> out = resampler.resample(surface, Variant::exact, pool);
  CHECK(out.size() > 3000);
  // About 7 vertices per point, in bricks of 64: a few hundred thousand slots
  // at most, i.e. a few tens of MiB, against 8.6e9 vertices in the grid.
  CHECK(resampler.stats().vertices < 20 * surface.points().size());
  CHECK(resampler.vertex_slots() < 500000);
}
