#include <doctest/doctest.h>

#include "core/shapes.hpp"
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
