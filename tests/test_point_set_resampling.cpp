#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <stdexcept>

#include "core/run/point_set_resampling.hpp"
#include "core/geometry/kd_tree.hpp"
#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"
#include "core/surface/local_support.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::half_sparse_sphere;
using amls::test::probes_in_holes;

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

TEST_CASE("without --grid or --spacing, h comes from the points, and the output does not depend on units or position") {
  PointSetResampling options;
  const PointSet<3> metres = sample_sphere(Vec<3>(2.0, 2.0, 2.0), 1.0, 3000);
  const SpacingChoice choice = choose_spacing(metres.positions, options);
  CHECK(choice.reason.find("4th nearest neighbour") != std::string::npos);
  const ResampledPointSet<3> a = resample_point_set(metres, options);
  CHECK(a.grid.spacing() == doctest::Approx(choice.h));
  CHECK(a.coverage.input_fraction() == 1.0);
  CHECK(a.coverage.output_fraction() == 1.0);

  // The same scan in millimetres, 10 km away.
  const double scale = 1000.0;
  const Vec<3> shift(1e4, -1e4, 1e4);
  PointSet<3> millimetres = metres;
  for (Vec<3>& p : millimetres.positions) p = scale * p + shift;
  const ResampledPointSet<3> b = resample_point_set(millimetres, options);
  CHECK(b.grid.spacing() == doctest::Approx(scale * a.grid.spacing()).epsilon(1e-9));
  REQUIRE(b.points.size() == a.points.size());
  CHECK(b.coverage.input_covered == a.coverage.input_covered);
  CHECK(b.coverage.output_on_input == a.coverage.output_on_input);
  // The same points up to rounding, maybe in another order: each of b's, mapped back, is one of a's.
  KdTree<3> tree;
  tree.build(a.points.positions);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  double worst = 0.0;
  for (const Vec<3>& p : b.points.positions) {
    tree.nearest((p - shift) / scale, 1, ids, squared);
    worst = std::max(worst, std::sqrt(squared.front()));
  }
  CHECK(worst < 1e-6 * a.grid.spacing());
}

TEST_CASE("--grid N: h = 1/N in the unit box, else the bounding box's longest side / N") {
  PointSetResampling options;
  options.grid = 64;
  const PointSet<2> inside = sample_circle(Vec<2>(0.5, 0.5), 0.25, 100);
  CHECK(choose_spacing(inside.positions, options).h == 1.0 / 64);
  const PointSet<2> outside = sample_circle(Vec<2>(10.0, 0.0), 4.0, 100);
  const SpacingChoice choice = choose_spacing(outside.positions, options);
  CHECK(choice.h == doctest::Approx(8.0 / 64).epsilon(1e-3));
  CHECK(choice.reason.find("longest side") != std::string::npos);
  options.spacing = 0.3;  // absolute, first
  CHECK(choose_spacing(outside.positions, options).h == 0.3);
}

TEST_CASE("a resampling whose output would be too large is refused before any grid is built, naming a spacing that fits") {
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.0, 0.0, 0.0), 1.0, 2000);
  const double area = sampled_extent(sphere.positions);
  CHECK(area == doctest::Approx(4.0 * std::numbers::pi).epsilon(0.15));
  PointSetResampling options;
  options.most_points = 1e5;
  const ResamplingCost fits = check_resampling_cost(3, area, 0.05, options);
  CHECK(fits.points == doctest::Approx(1.5 * area / 0.0025));
  CHECK_THROWS_WITH_AS(check_resampling_cost(3, area, 0.001, options),
                       doctest::Contains("more than the limit of 1e+05"), std::invalid_argument);
  try {
    check_resampling_cost(3, area, 0.001, options);
  } catch (const std::invalid_argument& e) {
    // The spacing it names passes the check.
    const std::string message = e.what();
    const double named = std::stod(message.substr(message.find("--spacing ") + 10));
    CHECK(check_resampling_cost(3, area, named, options).points <= options.most_points);
  }
  options.spacing = 0.001;
  CHECK_THROWS_AS(resample_point_set(sphere, options), std::invalid_argument);
  options.most_points = kMostResampledPoints;
  options.memory_mib = 1.0;  // a machine of 2 MiB: about 500 points
  CHECK_THROWS_WITH_AS(check_resampling_cost(3, area, 0.05, options), doctest::Contains("GiB of memory"),
                       std::invalid_argument);
}


TEST_CASE("supports widened where the input is sparse close a sphere sampled 4 x more sparsely on one half") {
  const PointSet<3> input = half_sparse_sphere(3000);
  PointSetResampling options;
  options.widen_support = true;
  // The dense half's h: the rule over a sphere sampled densely all over.
  options.spacing = sample_spacing<3>(sample_sphere(Vec<3>::Zero(), 1.0, 3000).positions).h;
  const double h = options.spacing;
  std::vector<Vec<3>> probes;
  for (const Vec<3>& p : sample_sphere(Vec<3>::Zero(), 1.0, 2000).positions)
    if (p.z() < -0.1) probes.push_back(p);

  const ResampledPointSet<3> widened = resample_point_set(input, options);
  CHECK(widened.widening.widened_points > 0);
  CHECK(widened.widening.widest > 2.0);
  CHECK(widened.widening.widest <= kMostWidening);
  CHECK(probes_in_holes(widened.points.positions, probes, 1.5 * h) == 0);
  CHECK(widened.coverage.gap_fraction() < 0.01);
  CHECK_FALSE(widened.coverage.clear_loss());
  double worst = 0.0;
  for (const Vec<3>& p : widened.points.positions) worst = std::max(worst, std::abs(p.norm() - 1.0));
  CHECK(worst < 0.5 * h);
  options.threads = 2;  // the same points for any thread count
  CHECK(resample_point_set(input, options).points.positions == widened.points.positions);

  options.threads = 1;
  options.widen_support = false;
  const ResampledPointSet<3> uniform = resample_point_set(input, options);
  CHECK(uniform.widening.widened_points == 0);
  CHECK(probes_in_holes(uniform.points.positions, probes, 1.5 * h) > probes.size() / 4);
  CHECK(uniform.coverage.input_fraction() < kLeastInputCovered);
  CHECK(uniform.coverage.clear_loss());
}

TEST_CASE("an evenly sampled input widens no support: the same output as one Delta for all") {
  PointSetResampling options;
  options.widen_support = true;
  const PointSet<3> sphere = sample_sphere(Vec<3>(3.0, -2.0, 1.0), 1.0, 2000);
  const ResampledPointSet<3> widened = resample_point_set(sphere, options);
  options.widen_support = false;
  const ResampledPointSet<3> uniform = resample_point_set(sphere, options);
  CHECK(widened.widening.widened_points == 0);
  REQUIRE(widened.points.size() == uniform.points.size());
  CHECK(widened.points.positions == uniform.points.positions);
  CHECK(widened.points.normals == uniform.points.normals);
}

TEST_CASE("an output much finer than the input, torn between the input points, fails on its gaps alone") {
  // 500 points on a sphere of radius 0.5 (spacing about 0.08) resampled at h = 0.01
  // with Delta = 12 h, which spans the input's spacing: F is defined all
  // over, but one Delta for all walks only h or so around each input point,
  // so the output is a dotted sphere: near every input point, and every
  // output point near one, yet torn everywhere between them.
  const PointSet<3> sphere = sample_sphere(Vec<3>(2.0, 2.0, 2.0), 0.5, 500);
  PointSetResampling options;
  options.spacing = 0.01;
  options.radius_factor = 12.0;
  options.widen_support = false;
  const ResampledPointSet<3> torn = resample_point_set(sphere, options);
  CHECK(torn.coverage.input_fraction() >= kLeastInputCovered);
  CHECK(torn.coverage.output_fraction() >= kLeastOutputOnInput);
  CHECK(torn.coverage.gap_fraction() > 0.5);
  CHECK(torn.coverage.clear_loss());
  CHECK(torn.coverage.loss_message().find("the output is torn") != std::string::npos);

  // Widened supports walk across the gaps and close it.
  options.widen_support = true;
  const ResampledPointSet<3> closed = resample_point_set(sphere, options);
  CHECK(closed.coverage.gap_fraction() < 0.01);
  CHECK_FALSE(closed.coverage.clear_loss());
}
