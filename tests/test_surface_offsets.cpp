// The 3D bias correction (core/surface/surface_offsets.hpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using namespace amls::test;

namespace {

AmlsParameters without_correction() {
  AmlsParameters p;
  p.bias_correction = false;
  return p;
}

}  // namespace

TEST_CASE("the bias correction leaves a sphere, which the fit reproduces, alone") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.2, 4000);
  const auto corrected = ready_surface(sphere, grid, pool);
  const auto plain = ready_surface(sphere, grid, pool, without_correction());
  REQUIRE(corrected.offsets().size() == corrected.points().size());
  CHECK(plain.offsets().empty());
  const double h = grid.spacing();
  for (const double o : corrected.offsets()) CHECK(std::abs(o) < 1e-9 * h);
  for (const Vec<3>& x : {Vec<3>(0.5, 0.5, 0.71), Vec<3>(0.62, 0.41, 0.5), Vec<3>(0.5, 0.3, 0.52)})
    CHECK(std::abs(corrected.evaluate(x).value - plain.evaluate(x).value) < 1e-9 * h);
}

TEST_CASE("on a thin cylinder the corrected surface passes through the points, the plain one outside them") {
  // A tube of radius 2.5 h: the sphere fit finds a sphere of about twice its
  // radius, whose zero set runs outside the points.
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> axis_point(0.5, 0.5, 0.5);
  const PointSet<3> tube = sample_cylinder(axis_point, 2.5 * h, 10.0 * h, 0.9 * h);
  const auto corrected = ready_surface(tube, grid, pool);
  const auto plain = ready_surface(tube, grid, pool, without_correction());
  int checked = 0;
  for (std::size_t i = 0; i < corrected.points().size(); ++i) {
    const Vec<3>& p = corrected.points().positions[i];
    if (std::abs(p.z() - axis_point.z()) > 4.0 * h) continue;  // away from the open ends
    ++checked;
    const double bias = plain.evaluate(p).value;  // outward normals: the points are inside
    CHECK(bias < -1e-3 * h);
    CHECK(corrected.offsets()[i] < 0.0);
    CHECK(std::abs(corrected.evaluate(p).value) < 0.1 * std::abs(bias));
  }
  CHECK(checked > 100);
}

TEST_CASE("F at a cube's corners in one pass includes the offsets as F corner by corner does") {
  ThreadPool pool(1);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  // Wide enough (8 h) for the normals near `near` to agree: the one-pass path.
  const auto tube = ready_surface(sample_cylinder(Vec<3>(0.5, 0.5, 0.5), 8.0 * h, 10.0 * h, 0.9 * h), grid, pool);
  const Vec<3> near(0.5 + 8.2 * h, 0.5, 0.5);
  std::vector<std::uint32_t> ids;
  tube.gather_ids(near, near, tube.radius() + 2.0 * h, ids);
  Neighbourhood<3> neighbourhood;
  tube.select(ids, near, tube.radius() + h, neighbourhood);
  REQUIRE(neighbourhood.offsets.size() == neighbourhood.positions.size());
  REQUIRE(neighbourhood.consistent);
  CHECK(std::any_of(neighbourhood.offsets.begin(), neighbourhood.offsets.end(), [](double o) { return o != 0.0; }));
  std::array<Vec<3>, 8> corners;
  for (int v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) corners[v][a] = near[a] + ((v >> a) & 1 ? 0.5 : -0.5) * h;
  std::array<Evaluation<3>, 8> values;
  tube.evaluate_cube(neighbourhood, corners, values);
  for (int v = 0; v < 8; ++v) {
    const Evaluation<3> single = tube.evaluate_in(neighbourhood, corners[v]);
    REQUIRE(single.defined);
    CHECK(values[v].value == doctest::Approx(single.value).epsilon(1e-12).scale(h));
    CHECK(values[v].value == doctest::Approx(tube.evaluate(corners[v]).value).epsilon(1e-12).scale(h));
  }
}

TEST_CASE("where the offsets change sign within Delta / 2 the limiter drops them") {
  // A sheet rippled at a wavelength of 6 h: the fit flattens the ripple, so
  // the offsets are of one sign on crests and of the other in troughs.
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const double amplitude = 0.5 * h, wavelength = 6.0 * h;
  PointSet<3> sheet;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double x = 0.3 + i * 0.8 * h, y = 0.3 + j * 0.8 * h;
      const double k = 2.0 * std::numbers::pi / wavelength;
      sheet.add(Vec<3>(x, y, 0.5 + amplitude * std::cos(k * x)),
                Vec<3>(amplitude * k * std::sin(k * x), 0.0, 1.0).normalized());
    }
  const auto s = ready_surface(sheet, grid, pool);
  const std::vector<Vec<3>>& p = s.points().positions;
  int zeros = 0, positive = 0, negative = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double o = s.offsets()[i];
    zeros += o == 0.0 ? 1 : 0;
    positive += o > 0.0 ? 1 : 0;
    negative += o < 0.0 ? 1 : 0;
    // No two points within Delta / 2 keep offsets of opposite signs.
    for (std::size_t j = 0; j < p.size(); ++j)
      if ((p[i] - p[j]).norm() <= 0.5 * s.radius()) CHECK_FALSE(o * s.offsets()[j] < 0.0);
  }
  CHECK(zeros > 0);
  CHECK(positive > 0);
  CHECK(negative > 0);
}

TEST_CASE("the offsets do not depend on the thread count, and 2D surfaces have none") {
  const Grid<3> grid = Grid<3>::unit(64);
  const PointSet<3> tube = sample_cylinder(Vec<3>(0.5, 0.5, 0.5), 3.0 * grid.spacing(), 0.1, 0.9 * grid.spacing());
  ThreadPool one(1), two(2);
  CHECK(ready_surface(tube, grid, one).offsets() == ready_surface(tube, grid, two).offsets());
  const auto circle = ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.05, 60), Grid<2>::unit(128), one);
  CHECK(circle.offsets().empty());
}
