#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "core/surface/curve_tracing.hpp"
#include "core/geometry/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::ready_surface;

namespace {

// The unit circle of 250 points on a grid of h = 0.024 whose origin is not aligned with it.
AmlsSurface<2> circle_surface(ThreadPool& pool) {
  const Grid<2> grid(Vec<2>(-1.1443, -1.1507), 0.024);
  return ready_surface(sample_circle(Vec<2>::Zero(), 1.0, 250), grid, pool);
}

}  // namespace

TEST_CASE("the traced curve of a sampled circle lies on the circle and has its length") {
  ThreadPool pool(2);
  const AmlsSurface<2> surface = circle_surface(pool);
  const TracedCurve curve = trace_curve(surface, pool);
  REQUIRE(curve.segments.size() > 250);
  double length = 0.0, worst = 0.0;
  for (const CurveSegment& s : curve.segments) {
    length += (s.b - s.a).norm();
    worst = std::max({worst, std::abs(s.a.norm() - 1.0), std::abs(s.b.norm() - 1.0)});
  }
  // Linear interpolation between vertices h / 2 apart: errors of order (h/2)^2 / 8.
  CHECK(worst < 1e-3);
  CHECK(length == doctest::Approx(2.0 * std::numbers::pi).epsilon(2e-3));
}

TEST_CASE("the traced curve of a closed curve is a closed chain: every endpoint is shared by two segments") {
  ThreadPool pool(1);
  const AmlsSurface<2> surface = circle_surface(pool);
  std::map<std::pair<double, double>, int> uses;
  for (const CurveSegment& s : trace_curve(surface, pool, {1, 1}).segments) {
    ++uses[{s.a.x(), s.a.y()}];
    ++uses[{s.b.x(), s.b.y()}];
  }
  REQUIRE(!uses.empty());
  for (const auto& [point, count] : uses) CHECK(count == 2);
}

TEST_CASE("tracing does not depend on the thread count") {
  ThreadPool one(1), three(3);
  const AmlsSurface<2> surface = circle_surface(one);
  const TracedCurve a = trace_curve(surface, one), b = trace_curve(surface, three);
  REQUIRE(a.segments.size() == b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    CHECK(a.segments[i].a == b.segments[i].a);
    CHECK(a.segments[i].b == b.segments[i].b);
  }
}

TEST_CASE("a surface without points traces nothing, and bad options are rejected") {
  ThreadPool pool(1);
  const Grid<2> grid(Vec<2>::Zero(), 0.1);
  const AmlsSurface<2> empty = ready_surface(PointSet<2>{}, grid, pool);
  CHECK(trace_curve(empty, pool).segments.empty());
  const AmlsSurface<2> surface = circle_surface(pool);
  CHECK_THROWS_AS(trace_curve(surface, pool, {0, 1}), std::invalid_argument);
  CHECK_THROWS_AS(trace_curve(surface, pool, {2, -1}), std::invalid_argument);
}

TEST_CASE("where the points are too sparse for F, the traced curve has gaps") {
  ThreadPool pool(1);
  // 40 points on the unit circle are 0.157 apart, more than 2 Delta = 0.144 at h = 0.024.
  const Grid<2> grid(Vec<2>(-1.2, -1.2), 0.024);
  const AmlsSurface<2> surface = ready_surface(sample_circle(Vec<2>::Zero(), 1.0, 40), grid, pool);
  double length = 0.0;
  for (const CurveSegment& s : trace_curve(surface, pool).segments) length += (s.b - s.a).norm();
  CHECK(length < 0.95 * 2.0 * std::numbers::pi);
}
