#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/geometry/coverage.hpp"
#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

// A square lattice of n x n points `step` apart in the plane z = 0.
std::vector<Vec<3>> lattice(int n, double step) {
  std::vector<Vec<3>> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) out.emplace_back(i * step, j * step, 0.0);
  return out;
}

}  // namespace

TEST_CASE("kth neighbour distances on a lattice: 4 neighbours at the step, the next 4 on the diagonal") {
  const std::vector<Vec<3>> points = lattice(10, 0.5);
  const std::vector<double> first = kth_neighbour_distances<3>(points, 1);
  const std::vector<double> fourth = kth_neighbour_distances<3>(points, 4);
  const std::vector<double> fifth = kth_neighbour_distances<3>(points, 5);
  const std::size_t inner = 5 * 10 + 5;  // away from the border
  CHECK(first[inner] == doctest::Approx(0.5));
  CHECK(fourth[inner] == doctest::Approx(0.5));
  CHECK(fifth[inner] == doctest::Approx(0.5 * std::sqrt(2.0)));
  CHECK(fourth[0] == doctest::Approx(1.0));  // a corner: (1,0), (0,1), (1,1), then (2,0)
}

TEST_CASE("the spacing rule: half the median distance to the 4th neighbour, whatever the units and position") {
  const std::vector<Vec<3>> points = lattice(20, 0.1);
  const SampleSpacing s = sample_spacing<3>(points);
  CHECK(s.points == 400);
  CHECK(s.nearest_median == doctest::Approx(0.1));
  CHECK(s.kth_median == doctest::Approx(0.1));
  CHECK(s.h == doctest::Approx(0.05));
  CHECK(s.explanation().find("4th nearest neighbour") != std::string::npos);

  std::vector<Vec<3>> moved = points;
  for (Vec<3>& p : moved) p = 1000.0 * p + Vec<3>(1e4, -1e4, 1e4);
  CHECK(sample_spacing<3>(moved).h == doctest::Approx(1000.0 * s.h).epsilon(1e-9));
}

TEST_CASE("the spacing rule sees across scan lines, where the nearest neighbour sees along them") {
  // Lines 0.1 apart, sampled every 0.01 along: the nearest neighbour is 0.01 away,
  // the 4th still on the line (0.02), so h follows the lines' own spacing and not
  // the gaps between them - the rule is robust, it does not close every gap.
  std::vector<Vec<3>> lines;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 100; ++i) lines.emplace_back(i * 0.01, j * 0.1, 0.0);
  const SampleSpacing s = sample_spacing<3>(lines);
  CHECK(s.nearest_median == doctest::Approx(0.01));
  CHECK(s.kth_median == doctest::Approx(0.02));
  CHECK(s.h == doctest::Approx(0.01));
}

TEST_CASE("the spacing rule refuses too few points, coincident points and non-finite ones") {
  CHECK_THROWS_WITH_AS(sample_spacing<3>(lattice(2, 1.0)), doctest::Contains("needs more than 4 points, got 4"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(sample_spacing<3>(std::vector<Vec<3>>(10, Vec<3>::Ones())), doctest::Contains("coincide"),
                       std::invalid_argument);
  std::vector<Vec<3>> broken = lattice(4, 1.0);
  broken[7][1] = std::nan("");
  CHECK_THROWS_WITH_AS(sample_spacing<3>(broken), doctest::Contains("point 7 has a non-finite coordinate"),
                       std::invalid_argument);
}

TEST_CASE("coverage: an output on the input covers it, a hole leaves its input uncovered") {
  const std::vector<Vec<2>> input = sample_circle(Vec<2>(0, 0), 1.0, 400).positions;
  const std::vector<Vec<2>> same = sample_circle(Vec<2>(0, 0), 1.0, 300).positions;
  const double h = 2.0 * std::numbers::pi / 300;
  const Coverage full = measure_coverage<2>(input, same, h);
  CHECK(full.input_covered == 400);
  CHECK(full.output_on_input == 300);
  CHECK_FALSE(full.clear_loss());
  CHECK(full.loss_message().empty());

  // The output misses the quarter x > 0, y > 0 and adds a circle elsewhere.
  std::vector<Vec<2>> holed;
  for (const Vec<2>& p : same)
    if (p[0] < 0.0 || p[1] < 0.0) holed.push_back(p);
  const std::size_t kept = holed.size();
  for (const Vec<2>& p : sample_circle(Vec<2>(5, 5), 0.5, 50).positions) holed.push_back(p);
  const Coverage c = measure_coverage<2>(input, holed, h);
  CHECK(c.input_fraction() == doctest::Approx(0.75).epsilon(0.02));
  CHECK(c.output_on_input == kept);
  CHECK(c.output_points == kept + 50);
  CHECK(c.clear_loss());
  CHECK(c.loss_message().find("the output misses part of the input") != std::string::npos);
  CHECK(c.loss_message().find("lie off the input") != std::string::npos);
  CHECK(c.worst_uncovered[0] > 0.0);  // the largest hole is in the missing quarter
  CHECK(c.worst_uncovered[1] > 0.0);

  const Coverage nothing = measure_coverage<2>(input, {}, h);
  CHECK(nothing.input_covered == 0);
  CHECK(nothing.clear_loss());
  CHECK_THROWS_AS(measure_coverage<2>(input, same, 0.0), std::invalid_argument);
}
