#include <doctest/doctest.h>

#include <array>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::ready_surface;

TEST_CASE("F of a sampled circle is the circle's algebraic distance near it, undefined far away") {
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  const Vec<2> c(0.5, 0.75);
  const auto s = ready_surface(sample_circle(c, 0.15, 150), grid, pool);
  for (const Vec<2>& x : {Vec<2>(0.5, 0.91), Vec<2>(0.39, 0.66), Vec<2>(0.64, 0.75)}) {
    const auto e = s.evaluate(x);
    REQUIRE(e.defined);
    CHECK(e.value == doctest::Approx(((x - c).squaredNorm() - 0.0225) / 0.3).epsilon(1e-9));
  }
  CHECK_FALSE(s.evaluate(c).defined);
  CHECK_FALSE(s.evaluate(Vec<2>(0.5, 0.75 + 0.15 + 3.01 * grid.spacing())).defined);
}

TEST_CASE("pseudo-normals of a sampled sphere are radial and keep the carried orientation") {
  ThreadPool pool(2);
  const Vec<3> c(0.5, 0.5, 0.5);
  PointSet<3> sphere = sample_sphere(c, 0.2, 4000);
  for (auto& n : sphere.normals) n = -n;  // inward orientation must survive
  const auto s = ready_surface(std::move(sphere), Grid<3>::unit(64), pool);
  for (std::size_t i = 0; i < s.points().size(); i += 97)
    CHECK(s.pseudo_normals()[i].dot(-(s.points().positions[i] - c).normalized()) > 1 - 1e-9);
}

namespace {

// evaluate_cube() against evaluate_in() at the corners of cubes around a
// surface point: the same value, gradient and definedness. Returns whether
// the neighbourhood's normals were consistent (the one-pass path).
template <int D>
bool check_cube_matches_single_evaluations(const AmlsSurface<D>& s, const Vec<D>& near) {
  const double h = s.grid().spacing();
  std::vector<std::uint32_t> ids;
  s.gather_ids(near, near, s.radius() + 2.0 * h, ids);
  Neighbourhood<D> neighbourhood;
  s.select(ids, near, s.radius() + h, neighbourhood);
  std::array<Vec<D>, AmlsSurface<D>::kCubeCorners> corners;
  for (int v = 0; v < AmlsSurface<D>::kCubeCorners; ++v) {
    corners[v] = near;
    for (int a = 0; a < D; ++a) corners[v][a] += ((v >> a) & 1 ? 0.5 : -0.5) * h;
  }
  std::array<Evaluation<D>, AmlsSurface<D>::kCubeCorners> values;
  s.evaluate_cube(neighbourhood, corners, values);
  for (int v = 0; v < AmlsSurface<D>::kCubeCorners; ++v) {
    const Evaluation<D> single = s.evaluate_in(neighbourhood, corners[v]);
    REQUIRE(values[v].defined == single.defined);
    CHECK(values[v].value == doctest::Approx(single.value).epsilon(1e-12).scale(h));
    CHECK((values[v].gradient - single.gradient).norm() < 1e-12);
  }
  return neighbourhood.consistent;
}

}  // namespace

TEST_CASE("F at a cube's corners in one pass equals F corner by corner, with and without the orientation filter") {
  ThreadPool pool(1);
  const auto circle = ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.2, 200), Grid<2>::unit(128), pool);
  CHECK(check_cube_matches_single_evaluations<2>(circle, Vec<2>(0.7, 0.5)));
  const auto sphere = ready_surface(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.2, 3000), Grid<3>::unit(64), pool);
  CHECK(check_cube_matches_single_evaluations<3>(sphere, Vec<3>(0.5, 0.5, 0.7)));
  // A filament thinner than Delta: two sheets with opposite normals, so the
  // neighbourhood is not consistent and each corner filters on its own.
  PointSet<2> strip;
  for (int k = 0; k < 100; ++k) {
    const double x = 0.3 + 0.004 * k;
    strip.add(Vec<2>(x, 0.5), Vec<2>(0.0, -1.0));
    strip.add(Vec<2>(x, 0.5 + 0.01), Vec<2>(0.0, 1.0));
  }
  const auto thin = ready_surface(std::move(strip), Grid<2>::unit(128), pool);
  CHECK_FALSE(check_cube_matches_single_evaluations<2>(thin, Vec<2>(0.5, 0.505)));
}

TEST_CASE("F from a neighbourhood selected with room to spare has the bits of F from one selected within Delta") {
  // The resampler's root finding reuses one selection for nearby edges
  // (Resampler::kReuseMargin): the extra points must weigh exactly 0 and must
  // not change which points the orientation filter keeps.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  const double h = grid.spacing();
  // A circle of diameter about 4 Delta: the wide selection holds the far
  // side, whose normals oppose the near side's, so only it needs the filter.
  const Vec<2> c(0.5, 0.5);
  const auto s = ready_surface(sample_circle(c, 0.05, 60), grid, pool);
  std::vector<std::uint32_t> ids;
  s.gather_ids(c, c, 0.2, ids);
  const Vec<2> centre = c + Vec<2>(0.05, 0.0);
  Neighbourhood<2> tight, wide;
  s.select(ids, centre, s.radius() + h, tight);
  s.select(ids, centre, s.radius() + 11.0 * h, wide);
  CHECK(tight.consistent);
  CHECK_FALSE(wide.consistent);
  REQUIRE(wide.positions.size() > tight.positions.size());
  for (double t = -1.0; t <= 1.0; t += 0.25) {
    const Vec<2> y = centre + Vec<2>(0.0, t * h);
    const Evaluation<2> a = s.evaluate_in(tight, y), b = s.evaluate_in(wide, y);
    REQUIRE(a.defined);
    CHECK(b.defined);
    CHECK(a.value == b.value);
    CHECK(a.gradient == b.gradient);
    CHECK(a.mean_normal == b.mean_normal);
  }
}
