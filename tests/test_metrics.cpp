#include <doctest/doctest.h>

#include "core/metrics.hpp"
#include "core/shapes.hpp"

using namespace amls;

TEST_CASE("metrics: per-point nearest-neighbour spacing stays with its point") {
  // Three points on a line, 1 and 3 h apart, and a fourth 0.5 h from the last.
  PointSet<2> points;
  const double h = 0.1;
  for (double x : {0.0, 0.1, 0.4, 0.45}) points.add(Vec<2>(x, 0.0), Vec<2>(0.0, 1.0));
  const std::vector<double> s = nearest_neighbour_spacing_per_point(points, h);
  REQUIRE(s.size() == 4);
  CHECK(s[0] == doctest::Approx(1.0));
  CHECK(s[1] == doctest::Approx(1.0));
  CHECK(s[2] == doctest::Approx(0.5));
  CHECK(s[3] == doctest::Approx(0.5));
  CHECK(nearest_neighbour_spacing_per_point(PointSet<2>{}, h).empty());
}

TEST_CASE("metrics: nearest distances between two sets, in units of h") {
  const PointSet<2> circle = sample_circle(Vec<2>::Zero(), 1.0, 400);
  const PointSet<2> bigger = sample_circle(Vec<2>::Zero(), 1.1, 4000);
  const DistanceStats d = nearest_distance_stats(circle.positions, bigger.positions, 0.05);
  CHECK(d.count == 400);
  CHECK(d.mean == doctest::Approx(2.0).epsilon(0.01));  // 0.1 apart = 2 h
  CHECK(d.max == doctest::Approx(2.0).epsilon(0.01));
  CHECK(nearest_distance_stats(circle.positions, circle.positions, 0.05).max == 0.0);
  CHECK_THROWS(nearest_distance_stats(circle.positions, std::vector<Vec<2>>{}, 0.05));
  const std::vector<double> spacings = nearest_neighbour_spacings(circle, 0.01);
  CHECK(spacings.size() == 400);
  CHECK(spacing_stats_of(spacings).median == doctest::Approx(2.0 * std::sin(3.14159265358979 / 400) / 0.01));
}
