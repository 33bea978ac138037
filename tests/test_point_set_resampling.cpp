#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "core/run/point_set_resampling.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

TEST_CASE("resampling a circle once puts the new points on it, evenly spaced") {
  PointSetResampling options;
  options.grid = 64;
  const Vec<2> center(0.5, 0.5);
  const ResampledPointSet<2> out = resample_point_set(sample_circle(center, 0.25, 120), options);
  CHECK(out.grid.origin() == Vec<2>::Zero());  // inside the unit square: the unit grid
  REQUIRE(out.points.size() > 80);
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    CHECK(std::abs((out.points.positions[i] - center).norm() - 0.25) < 1e-10);
    CHECK(out.points.normals[i].dot((out.points.positions[i] - center).normalized()) > 0.999999);
  }
  CHECK(out.spacing_h.min > 0.25);
  CHECK(out.spacing_h.max < 2.0);
  CHECK(out.stats.points_before == 120);
  CHECK(out.stats.points_after == out.points.size());
}

TEST_CASE("a set outside the unit box gets a grid at its padded bounding box") {
  PointSetResampling options;
  options.spacing = 0.5;
  const Vec<3> center(100.0, -40.0, 7.0);
  const ResampledPointSet<3> out = resample_point_set(sample_sphere(center, 4.0, 2000), options);
  const double pad = 2.0 * options.radius_factor * options.spacing;
  CHECK((out.grid.origin() - (center - Vec<3>::Constant(4.0 + pad))).norm() < 0.05);
  REQUIRE(out.points.size() > 500);
  double worst = 0.0;
  for (const Vec<3>& p : out.points.positions) worst = std::max(worst, std::abs((p - center).norm() - 4.0));
  CHECK(worst < 1e-6);
}

TEST_CASE("resampling refuses an empty set, missing normals and bad grids") {
  PointSetResampling options;
  CHECK_THROWS_WITH_AS(resample_point_set(PointSet<2>{}, options), doctest::Contains("the input is empty"),
                       std::invalid_argument);
  PointSet<2> unoriented = sample_circle(Vec<2>(0.5, 0.5), 0.25, 50);
  unoriented.normals[3] = Vec<2>::Zero();
  CHECK_THROWS_WITH_AS(resample_point_set(unoriented, options),
                       doctest::Contains("needs oriented normals: point 3 has a zero or non-finite normal"),
                       std::invalid_argument);
  options.spacing = -1.0;
  CHECK_THROWS_WITH_AS(resample_point_set(sample_circle(Vec<2>(0.5, 0.5), 0.25, 50), options),
                       doctest::Contains("--spacing: must be within [1e-09, 1e+09]"), std::invalid_argument);
  options.spacing = 1e-9;
  CHECK_THROWS_WITH_AS(resample_point_set(sample_sphere(Vec<3>(5, 5, 5), 1.0, 50), options),
                       doctest::Contains("use a larger --spacing"), std::invalid_argument);
}
