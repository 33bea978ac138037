#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "core/surface/metrics.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

// Every normal is unit and points away from the shape's interior, told by `outward`.
template <int D, typename Outward>
void check_normals(const PointSet<D>& set, Outward&& outward) {
  REQUIRE(set.size() > 0);
  for (std::size_t i = 0; i < set.size(); ++i) {
    CHECK(set.normals[i].norm() == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(set.normals[i].dot(outward(set.positions[i])) > 0.0);
  }
}

}  // namespace

TEST_CASE("shapes: samplers give unit outward normals at about the asked spacing") {
  const double s = 0.05;
  SUBCASE("ellipse: points on it, normals along the gradient of x^2/a^2 + y^2/b^2") {
    const PointSet<2> e = sample_ellipse(Vec<2>(1, 2), Vec<2>(1.0, 0.5), s);
    for (std::size_t i = 0; i < e.size(); ++i) {
      const Vec<2> p = e.positions[i] - Vec<2>(1, 2);
      CHECK(p.x() * p.x() + 4 * p.y() * p.y() == doctest::Approx(1.0).epsilon(1e-9));
      CHECK((e.normals[i] - Vec<2>(p.x(), 4 * p.y()).normalized()).norm() < 1e-9);
    }
    const SpacingStats st = spacing_stats(e, s);
    CHECK(st.min > 0.95);  // even in arc length: chords barely shorter than the spacing
    CHECK(st.max < 1.05);
  }
  SUBCASE("torus") {
    const PointSet<3> t = sample_torus(Vec<3>::Zero(), 1.0, 0.3, s);
    check_normals<3>(t, [](const Vec<3>& p) {
      const Vec<3> ring = Vec<3>(p.x(), p.y(), 0).normalized();
      return Vec<3>(p - ring);
    });
    const SpacingStats st = spacing_stats(t, s);
    CHECK(st.median == doctest::Approx(1.0).epsilon(0.25));
    CHECK(st.max < 1.3);
    CHECK(t.size() == doctest::Approx(4 * std::numbers::pi * std::numbers::pi * 0.3 / (s * s)).epsilon(0.2));
  }
  SUBCASE("rounded box in 3D and 2D: on the surface at distance r from the inner box") {
    const Vec<3> half(0.5, 0.3, 0.2);
    const double r = 0.1;
    const PointSet<3> b = sample_rounded_box(Vec<3>::Zero(), half, r, s);
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec<3> inner = (half.array() - r).matrix();
      const Vec<3> nearest = b.positions[i].cwiseMax(-inner).cwiseMin(inner);
      CHECK((b.positions[i] - nearest).norm() == doctest::Approx(r).epsilon(1e-9));
      CHECK((b.positions[i] - nearest).normalized().dot(b.normals[i]) == doctest::Approx(1.0).epsilon(1e-9));
    }
    const SpacingStats st = spacing_stats(b, s);
    CHECK(st.median == doctest::Approx(1.0).epsilon(0.25));
    CHECK(st.max < 1.3);
    const PointSet<2> b2 = sample_rounded_box(Vec<2>::Zero(), Vec<2>(0.5, 0.25), 0.1, s);
    check_normals<2>(b2, [](const Vec<2>& p) { return p; });
    CHECK(spacing_stats(b2, s).max < 1.1);
    CHECK_THROWS(sample_rounded_box(Vec<2>::Zero(), Vec<2>(0.5, 0.25), 0.3, s));
  }
  SUBCASE("sphere and circle counts for a spacing") {
    const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points_for_spacing(1.0, s));
    check_normals<3>(sphere, [](const Vec<3>& p) { return p; });
    CHECK(spacing_stats(sphere, s).median == doctest::Approx(1.0).epsilon(0.2));
    CHECK(circle_points_for_spacing(1.0, 2 * std::numbers::pi / 250) == 250);
  }
}
