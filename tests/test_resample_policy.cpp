#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/run/flow_test.hpp"
#include "core/geometry/coverage.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

constexpr double kH = 0.01;
constexpr double kPi = std::numbers::pi;

// The band's verdict on `points` at step 3 (not the first step, which always resamples).
template <int D>
bool out_of_band(const PointSet<D>& points) {
  ThreadPool pool(1);
  return ResamplePolicy::parse("auto").resample_now<D>(3, points, kH, pool);
}

template <int D>
SamplingQuality quality_of(const PointSet<D>& points) {
  ThreadPool pool(1);
  return sampling_quality(points, kH, ResamplePolicy{}.search_radius(), pool);
}

// Points on the circle (0.5, 0.5), r = 0.2, at the given angles, with outward normals.
template <typename Angles>
PointSet<2> circle_at(const Angles& angles) {
  PointSet<2> set;
  for (const double a : angles) {
    const Vec<2> n(std::cos(a), std::sin(a));
    set.add(Vec<2>(0.5, 0.5) + 0.2 * n, n);
  }
  return set;
}

// The chord of an arc of `angle` on that circle, in units of h.
double chord_h(double angle) { return 2.0 * 0.2 * std::sin(0.5 * angle) / kH; }

}  // namespace

TEST_CASE("resample policies parse, print, and reject bad forms with a message") {
  CHECK(ResamplePolicy::parse("always").kind == ResamplePolicy::Kind::always);
  CHECK(ResamplePolicy::parse("auto").kind == ResamplePolicy::Kind::automatic);
  const ResamplePolicy every = ResamplePolicy::parse("every:5");
  CHECK(every.kind == ResamplePolicy::Kind::every);
  CHECK(every.every == 5);
  CHECK(every.to_string() == "every:5");
  CHECK(ResamplePolicy::parse("local").kind == ResamplePolicy::Kind::local);
  CHECK(ResamplePolicy::parse("local").to_string() == "local");
  for (const char* bad : {"sometimes", "every:", "every:0", "every:3x", "every:-2"})
    CHECK_THROWS_WITH_AS(ResamplePolicy::parse(bad), doctest::Contains("always, auto, local or every:K"),
                         std::invalid_argument);
}

TEST_CASE("sampling quality of circles: the gap is the spacing, the feature size the radius") {
  // 150 points on r = 0.2: 0.84 h apart; every pair of neighbours turns like the circle.
  const PointSet<2> even = sample_circle(Vec<2>(0.5, 0.5), 0.2, 150);
  const SamplingQuality q = quality_of(even);
  CHECK(q.gap == doctest::Approx(chord_h(2.0 * kPi / 150)).epsilon(1e-9));
  CHECK(q.feature_size == doctest::Approx(20.0).epsilon(1e-9));
  CHECK_FALSE(out_of_band(even));
  ThreadPool pool(1);
  CHECK(ResamplePolicy::parse("auto").resample_now<2>(0, even, kH, pool));  // the first step always resamples

  // A circle of radius 1.2 h is sharper than the grid walk keeps (feature 1.2 < 1.4), one of 2 h is not.
  CHECK(quality_of(sample_circle(Vec<2>(0.5, 0.5), 1.2 * kH, 9)).feature_size == doctest::Approx(1.2));
  CHECK(out_of_band(sample_circle(Vec<2>(0.5, 0.5), 1.2 * kH, 9)));
  CHECK_FALSE(out_of_band(sample_circle(Vec<2>(0.5, 0.5), 2.0 * kH, 15)));

  // Crowding alone stays in band: 1000 points 0.13 h apart define the same curve.
  CHECK_FALSE(out_of_band(sample_circle(Vec<2>(0.5, 0.5), 0.2, 1000)));
}

TEST_CASE("the gap sees holes, stretching and clustering that nearest-neighbour spacing misses") {
  const double step = 2.0 * kPi / 150;
  std::vector<double> angles;
  SUBCASE("one point missing: the gap is two spacings, still in band") {
    for (int k = 0; k < 150; ++k)
      if (k != 40) angles.push_back(k * step);
    const PointSet<2> set = circle_at(angles);
    CHECK(quality_of(set).gap == doctest::Approx(chord_h(2.0 * step)).epsilon(1e-9));
    CHECK_FALSE(out_of_band(set));
  }
  SUBCASE("a hole of five spacings: its rims are not surrounded") {
    for (int k = 0; k < 150; ++k)
      if (k < 40 || k > 44) angles.push_back(k * step);
    const PointSet<2> set = circle_at(angles);
    CHECK(quality_of(set).gap == std::numeric_limits<double>::infinity());
    CHECK(out_of_band(set));
  }
  SUBCASE("a stretched part: pairs 0.3 h apart, 3 h between the pairs") {
    // Every point has a neighbour 0.3 h away, so nearest-neighbour spacing sees nothing.
    for (int k = 0; k < 100; ++k) angles.push_back(k * step);
    const double pair = 0.3 * kH / 0.2;
    const double between = 3.0 * kH / 0.2;
    for (double a = 100 * step; a + pair < 2.0 * kPi - step; a += pair + between) {
      angles.push_back(a);
      angles.push_back(a + pair);
    }
    const PointSet<2> set = circle_at(angles);
    CHECK(quality_of(set).gap > 2.5);
    CHECK(out_of_band(set));
  }
  SUBCASE("a clustered part: 120 of 150 points on a tenth of the circle leave the rest 3.8 h apart") {
    for (int k = 0; k < 120; ++k) angles.push_back(0.2 * kPi * k / 120.0);
    for (int k = 0; k < 30; ++k) angles.push_back(0.2 * kPi + 1.8 * kPi * (k + 0.5) / 30.0);
    const PointSet<2> set = circle_at(angles);
    CHECK(quality_of(set).gap > 2.5);
    CHECK(out_of_band(set));
  }
}

TEST_CASE("the two sides of a thin filament do not count as one sheet") {
  // A ring 1 h thick: the outer circle's normals point out, the inner one's in,
  // 0.84 h apart along each. Across the ring the normals are opposite, so they
  // neither surround each other nor count as a sharp turn.
  PointSet<2> ring = sample_circle(Vec<2>(0.5, 0.5), 0.2, 150);
  const PointSet<2> inner = sample_circle(Vec<2>(0.5, 0.5), 0.19, 143);
  for (std::size_t i = 0; i < inner.size(); ++i) ring.add(inner.positions[i], -inner.normals[i]);
  const SamplingQuality q = quality_of(ring);
  CHECK(q.gap < 1.0);
  CHECK(q.feature_size == doctest::Approx(19.0).epsilon(1e-9));
  CHECK_FALSE(out_of_band(ring));
}

TEST_CASE("sampling quality of spheres: in band when even, out with a hole, a stretch or a sharp cap") {
  // 7000 points on r = 0.2: about 0.9 h apart.
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.2, 7000);
  const SamplingQuality q = quality_of(sphere);
  CHECK(q.gap < 1.5);
  CHECK(q.feature_size == doctest::Approx(20.0).epsilon(1e-9));
  CHECK_FALSE(out_of_band(sphere));

  SUBCASE("a hole: the points within 3 h of the north pole removed") {
    PointSet<3> holed;
    for (std::size_t i = 0; i < sphere.size(); ++i)
      if ((sphere.positions[i] - Vec<3>(0.5, 0.5, 0.7)).norm() > 0.03)
        holed.add(sphere.positions[i], sphere.normals[i]);
    CHECK(quality_of(holed).gap == std::numeric_limits<double>::infinity());
    CHECK(out_of_band(holed));
  }
  SUBCASE("stretched fourfold along x: rows of points 3 h apart") {
    PointSet<3> stretched;
    for (std::size_t i = 0; i < sphere.size(); ++i) {
      const Vec<3> d = sphere.positions[i] - Vec<3>(0.5, 0.5, 0.5);
      const Vec<3> n = sphere.normals[i];
      // Positions x -> 4x; normals by the inverse transpose.
      stretched.add(Vec<3>(0.5 + 4.0 * d.x(), 0.5 + d.y(), 0.5 + d.z()),
                    Vec<3>(n.x() / 4.0, n.y(), n.z()).normalized());
    }
    const SamplingQuality s = quality_of(stretched);
    CHECK(s.gap > 2.5);
    CHECK(s.feature_size > 1.4);  // the sharpest curvature radius there is b^2 / a = 5 h
    CHECK(out_of_band(stretched));
  }
  SUBCASE("a sphere of radius 1.2 h") {
    const PointSet<3> small = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 1.2 * kH, 20);
    CHECK(quality_of(small).feature_size == doctest::Approx(1.2));
    CHECK(out_of_band(small));
  }
}

TEST_CASE("on a resampled box with flat faces more reach finds no more points in gaps, and none at 2.5 h") {
  // A box with sharp edges, turned off the axes, resampled: along its flat
  // faces many points have two neighbours in one line (at h and 2 h) whose
  // directions differ by far less than 1e-8 radians. A sector test that could
  // not order them found 5,494 of 23,135 points unsurrounded within 2.5 h
  // but 1 within 2 h.
  PointSet<3> box = sample_rounded_box(Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.3, 0.2, 0.25), 0.0, 0.01);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Vec<3>(1, 2, 3).normalized()).toRotationMatrix();
  for (std::size_t i = 0; i < box.size(); ++i) {
    box.positions[i] = Vec<3>::Constant(0.5) + turn * (box.positions[i] - Vec<3>::Constant(0.5));
    box.normals[i] = turn * box.normals[i];
  }
  PointSetResampling options;
  options.spacing = 1.0 / 128;
  const PointSet<3> resampled = resample_point_set(box, options).points;
  REQUIRE(resampled.size() > 20000);
  ThreadPool pool(1);
  std::size_t previous = resampled.size();
  for (const double reach : {1.5, 2.0, 2.2, 2.5, 3.0, 4.0}) {
    const std::size_t unsurrounded = unsurrounded_points(resampled, options.spacing, reach, pool);
    CAPTURE(reach);
    CHECK(unsurrounded <= previous);
    previous = unsurrounded;
  }
  CHECK(unsurrounded_points(resampled, options.spacing, kGapReach, pool) == 0);
  CHECK(sampling_quality(resampled, options.spacing, ResamplePolicy{}.search_radius(), pool).gap < 2.5);
}

TEST_CASE("sampling quality does not depend on the thread count") {
  // An uneven set: a sphere squeezed along z with a wobble.
  PointSet<3> set;
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.2, 3000);
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    const Vec<3> d = sphere.positions[i] - Vec<3>(0.5, 0.5, 0.5);
    const double w = 1.0 + 0.3 * std::sin(20.0 * d.x());
    set.add(Vec<3>(0.5 + d.x(), 0.5 + d.y(), 0.5 + 0.5 * w * d.z()), sphere.normals[i]);
  }
  ThreadPool one(1);
  ThreadPool two(2);
  ThreadPool three(3);
  const SamplingQuality a = sampling_quality(set, kH, 2.5, one);
  for (ThreadPool* pool : {&two, &three}) {
    const SamplingQuality b = sampling_quality(set, kH, 2.5, *pool);
    CHECK(a.gap == b.gap);
    CHECK(a.feature_size == b.feature_size);
  }
}

TEST_CASE("the flow test counts its resamples under every policy") {
  FlowTestConfig config;
  // Coarse, but not so coarse that the run stops early (at 64^2 the point set
  // can grow past 20x before step 200, depending on the last bits of the roots).
  config.grid = 128;
  config.dt = 0.04;
  config.resample = ResamplePolicy::parse("every:4");
  const FlowTestReport report = run_vortex_test(config).report;
  REQUIRE(report.steps == 200);
  CHECK(report.resamples == 50);  // steps 0, 4, ..., 196 of 200
}

TEST_CASE("on the 128^2 vortex auto resamples half as often as always, ends closed and no less accurate") {
  FlowTestConfig config;
  config.grid = 128;
  config.resample = ResamplePolicy::parse("always");
  const FlowTestReport always = run_vortex_test(config).report;
  config.resample = ResamplePolicy::parse("auto");
  const FlowTestReport automatic = run_vortex_test(config).report;
  REQUIRE_FALSE(always.broken);
  CHECK(always.resamples == 800);
  CHECK_FALSE(automatic.broken);
  CHECK(automatic.resamples < 450);  // 382 when written
  CHECK(automatic.l1_error < 1.1 * always.l1_error);
}
