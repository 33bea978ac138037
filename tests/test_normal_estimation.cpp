#include <doctest/doctest.h>

#include <random>

#include "core/surface/normal_estimation.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

// The points of `exact` with their normals scrambled: random directions, random signs.
template <int D>
PointSet<D> scrambled(const PointSet<D>& exact) {
  PointSet<D> out = exact;
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (Vec<D>& n : out.normals)
    for (int a = 0; a < D; ++a) n[a] = normal(random);
  return out;
}

// Every estimated normal within `degrees` of the exact outward one.
template <int D>
void check_oriented(const PointSet<D>& estimated, const PointSet<D>& exact, double degrees) {
  std::size_t wrong = 0;
  double worst = 1.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    CHECK(estimated.normals[i].norm() == doctest::Approx(1.0));
    const double c = estimated.normals[i].dot(exact.normals[i]);
    if (c < 0.0) ++wrong;
    worst = std::min(worst, c);
  }
  CHECK(wrong == 0);
  CHECK(worst > std::cos(degrees * 3.14159265358979 / 180.0));
}

}  // namespace

TEST_CASE("normal estimation: a sphere's and a torus's normals come out outward from scrambled ones") {
  ThreadPool pool(2);
  SUBCASE("sphere") {
    const PointSet<3> exact = sample_sphere(Vec<3>(0.3, -0.2, 0.1), 0.5, 3000);
    PointSet<3> points = scrambled(exact);
    const NormalEstimation report = estimate_normals(points, 0.08, pool);
    check_oriented(points, exact, 3.0);
    CHECK(report.components == 1);
    CHECK(report.failed_fits == 0);
    CHECK(report.warnings.empty());
  }
  SUBCASE("torus: orientation crosses the hole's side, where normals point inward to the axis") {
    const PointSet<3> exact = sample_torus(Vec<3>::Zero(), 1.0, 0.35, 0.05);
    PointSet<3> points = scrambled(exact);
    const NormalEstimation report = estimate_normals(points, 0.15, pool);
    check_oriented(points, exact, 3.0);
    CHECK(report.components == 1);
  }
  SUBCASE("2D: an ellipse") {
    const PointSet<2> exact = sample_ellipse(Vec<2>::Zero(), Vec<2>(1.0, 0.4), 0.02);
    PointSet<2> points = scrambled(exact);
    estimate_normals(points, 0.06, pool);
    check_oriented(points, exact, 3.0);
  }
}

TEST_CASE("normal estimation: separate parts are each oriented, with a warning") {
  ThreadPool pool(1);
  PointSet<3> exact = sample_sphere(Vec<3>(-2, 0, 0), 0.5, 800);
  const PointSet<3> other = sample_sphere(Vec<3>(2, 0, 0), 0.5, 800);
  for (std::size_t i = 0; i < other.size(); ++i) exact.add(other.positions[i], other.normals[i]);
  PointSet<3> points = scrambled(exact);
  const NormalEstimation report = estimate_normals(points, 0.15, pool);
  check_oriented(points, exact, 5.0);
  CHECK(report.components == 2);
  REQUIRE(report.warnings.size() >= 1);
  CHECK(report.warnings[0].find("2 separate parts") != std::string::npos);
  PointSet<3> few;
  few.add(Vec<3>::Zero(), Vec<3>::Zero());
  CHECK_THROWS(estimate_normals(few, 0.1, pool));
}

namespace {

// The samples of `sphere` on one side of the plane z = cut: above, a cap; below, a bowl.
PointSet<3> sphere_part(const PointSet<3>& sphere, double cut, bool above) {
  PointSet<3> part;
  for (std::size_t i = 0; i < sphere.size(); ++i)
    if ((sphere.positions[i].z() > cut) == above) part.add(sphere.positions[i], sphere.normals[i]);
  return part;
}

}  // namespace

TEST_CASE("normal estimation: an open surface takes its convex side, a flat one keeps up") {
  ThreadPool pool(1);
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 6000);
  // A bowl's highest points are on its rim, a cap's inside it: both come out on the convex side.
  for (const bool above : {false, true}) {
    CAPTURE(above);
    const PointSet<3> part = sphere_part(sphere, above ? 0.3 : -0.3, above);
    PointSet<3> points = scrambled(part);
    const NormalEstimation report = estimate_normals(points, 0.12, pool);
    check_oriented(points, part, 5.0);
    CHECK(report.turned_parts == (above ? 0 : 1));
  }
  SUBCASE("a noisy plane: up") {
    PointSet<3> plane;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> noise(-0.002, 0.002);
    for (int j = 0; j < 40; ++j)
      for (int i = 0; i < 40; ++i) plane.add(Vec<3>(0.05 * i + noise(random), 0.05 * j + noise(random), noise(random)),
                                              Vec<3>(0, 0, 1));
    PointSet<3> points = scrambled(plane);
    const NormalEstimation report = estimate_normals(points, 0.15, pool);
    check_oriented(points, plane, 10.0);
    CHECK(report.turned_parts == 0);
  }
}
