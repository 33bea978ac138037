#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/io/surface_samples.hpp"
#include "core/surface/broken_normals.hpp"

using namespace amls;

namespace {

// The ids of the `count` points nearest to point `centre` (itself included).
std::vector<std::size_t> nearest(const std::vector<Vec<3>>& positions, std::size_t centre, std::size_t count) {
  std::vector<std::size_t> ids(positions.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  std::partial_sort(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(count), ids.end(),
                    [&](std::size_t a, std::size_t b) {
                      return (positions[a] - positions[centre]).squaredNorm() <
                             (positions[b] - positions[centre]).squaredNorm();
                    });
  ids.resize(count);
  std::sort(ids.begin(), ids.end());
  return ids;
}

// A sphere of 3,000 samples (spacing about 0.065) with every 37th normal
// turned inward and a cluster of 4 neighbours turned together (a fifth or
// more of the about 30 points within the test's reach would be a patch of
// its own: BrokenNormals::kAgreeing); `broken` gets their ids in order.
PointSet<3> sphere_with_broken_normals(std::vector<std::size_t>& broken) {
  PointSet<3> points = sample_sphere(Vec<3>::Zero(), 1.0, 3000);
  broken = nearest(points.positions, 1000, 4);
  for (std::size_t i = 0; i < points.size(); i += 37) broken.push_back(i);
  std::sort(broken.begin(), broken.end());
  broken.erase(std::unique(broken.begin(), broken.end()), broken.end());
  for (const std::size_t i : broken) points.normals[i] = -points.normals[i];
  return points;
}

// Two square sheets of 30 x 30 samples at spacing 0.05, `gap` apart along z,
// their normals facing away from each other: a thin plate's two sides.
PointSet<3> plate(double gap) {
  PointSet<3> points;
  for (const double side : {1.0, -1.0})
    for (int j = 0; j < 30; ++j)
      for (int i = 0; i < 30; ++i) points.add(Vec<3>(0.05 * i, 0.05 * j, 0.5 * gap * side), Vec<3>(0, 0, side));
  return points;
}

// A cube of side 1, each face a grid of 20 x 20 samples with the face's normal:
// sharp edges, where neighbours' normals are perpendicular.
PointSet<3> cube() {
  PointSet<3> points;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {0.0, 1.0})
      for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) {
          Vec<3> p;
          p[axis] = side;
          p[(axis + 1) % 3] = (i + 0.5) / 20.0;
          p[(axis + 2) % 3] = (j + 0.5) / 20.0;
          Vec<3> n = Vec<3>::Zero();
          n[axis] = side > 0.5 ? 1.0 : -1.0;
          points.add(p, n);
        }
  return points;
}

}  // namespace

TEST_CASE("broken normals: a closed sphere's broken normals, alone and in a cluster, are turned back") {
  std::vector<std::size_t> broken_ids;
  const PointSet<3> exact = sample_sphere(Vec<3>::Zero(), 1.0, 3000);
  for (const int threads : {1, 2}) {
    CAPTURE(threads);
    PointSet<3> points = sphere_with_broken_normals(broken_ids);
    ThreadPool pool(threads);
    const BrokenNormals broken = mend_broken_normals<3>(points.positions, points.normals, 0.2, pool);
    CHECK(broken.turned == broken_ids);
    CHECK(broken.rounds >= 1);
    CHECK(points.normals == exact.normals);
  }
  SUBCASE("a set without broken normals is left as it is") {
    PointSet<3> points = exact;
    ThreadPool pool(2);
    const BrokenNormals broken = mend_broken_normals<3>(points.positions, points.normals, 0.2, pool);
    CHECK(broken.turned.empty());
    CHECK(broken.rounds == 0);
    CHECK(points.normals == exact.normals);
  }
}

TEST_CASE("broken normals: a thin plate's two sides and a cube's sharp edges are no broken normals") {
  ThreadPool pool(2);
  const double spacing = 0.05, radius = 3.0 * spacing;
  for (const double gap : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    CAPTURE(gap);
    PointSet<3> points = plate(gap * spacing);
    const std::vector<Vec<3>> given = points.normals;
    CHECK(mend_broken_normals<3>(points.positions, points.normals, radius, pool).turned.empty());
    CHECK(points.normals == given);
  }
  SUBCASE("a broken normal on a plate twice the spacing thick is turned, the other side's are not") {
    PointSet<3> points = plate(2.0 * spacing);
    const std::size_t middle = 15 * 30 + 15;
    points.normals[middle] = -points.normals[middle];
    const BrokenNormals broken = mend_broken_normals<3>(points.positions, points.normals, radius, pool);
    CHECK(broken.turned == std::vector<std::size_t>{middle});
    CHECK(points.normals[middle] == Vec<3>(0, 0, 1));
  }
  SUBCASE("cube") {
    PointSet<3> points = cube();
    CHECK(mend_broken_normals<3>(points.positions, points.normals, radius, pool).turned.empty());
  }
}

TEST_CASE("broken normals: normals across the surface are replaced by their neighbours' mean direction") {
  const PointSet<3> exact = sample_sphere(Vec<3>::Zero(), 1.0, 3000);
  PointSet<3> points = exact;
  std::vector<std::size_t> crosswise;
  for (std::size_t i = 5; i < points.size(); i += 41) {
    // Tipped 70 to 110 degrees off the surface's normal, towards a tangent.
    const Vec<3>& n = exact.normals[i];
    const Vec<3> tangent = n.cross(std::abs(n.x()) < 0.9 ? Vec<3>::UnitX() : Vec<3>::UnitY()).normalized();
    const double tip = (70.0 + static_cast<double>(i % 41)) * std::numbers::pi / 180.0;
    points.normals[i] = std::cos(tip) * n + std::sin(tip) * tangent;
    crosswise.push_back(i);
  }
  ThreadPool pool(2);
  const BrokenNormals broken = mend_broken_normals<3>(points.positions, points.normals, 0.2, pool);
  CHECK(broken.turned.empty());
  CHECK(broken.replaced == crosswise);
  double worst = 1.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    CHECK(points.normals[i].norm() == doctest::Approx(1.0));
    worst = std::min(worst, points.normals[i].dot(exact.normals[i]));
  }
  CHECK(worst > std::cos(5.0 * std::numbers::pi / 180.0));  // the mean of neighbours within 0.2 of a unit sphere
  SUBCASE("one tipped 50 degrees is left as it is") {
    PointSet<3> tipped = exact;
    const Vec<3>& n = exact.normals[100];
    const Vec<3> tangent = n.cross(Vec<3>::UnitZ()).normalized();
    tipped.normals[100] = std::cos(0.87) * n + std::sin(0.87) * tangent;
    const Vec<3> given = tipped.normals[100];
    const BrokenNormals none = mend_broken_normals<3>(tipped.positions, tipped.normals, 0.2, pool);
    CHECK(none.replaced.empty());
    CHECK(tipped.normals[100] == given);
  }
}

TEST_CASE("broken normals: in 2D, a circle's broken normals") {
  PointSet<2> points = sample_circle(Vec<2>(0.5, -0.25), 1.0, 400);
  const std::vector<Vec<2>> exact = points.normals;
  for (const std::size_t i : {3, 150, 151, 300}) points.normals[i] = -points.normals[i];
  ThreadPool pool(1);
  const BrokenNormals broken = mend_broken_normals<2>(points.positions, points.normals, 0.05, pool);
  CHECK(broken.turned == std::vector<std::size_t>{3, 150, 151, 300});
  CHECK(points.normals == exact);
}

TEST_CASE("broken normals: a point set opened with normals has its broken ones turned, with a warning") {
  std::vector<std::size_t> broken_ids;
  SurfaceInput input;
  input.path = "sphere.ply";
  input.point_set.points = sphere_with_broken_normals(broken_ids);
  input.point_set.has_normals = true;
  SurfaceSampleOptions options;
  options.normal_radius = 0.2;
  options.threads = 2;
  const SurfaceSamples samples = surface_samples(input, options);
  CHECK(samples.points.normals == sample_sphere(Vec<3>::Zero(), 1.0, 3000).normals);
  REQUIRE(samples.warnings.size() == 1);
  CHECK(samples.warnings[0].find("sphere.ply: " + std::to_string(broken_ids.size()) +
                                 " normals pointed against those of the points beside them and were turned over (within 0.2; the first at ") == 0);
  SUBCASE("no reach, no test: the normals as given") {
    options.normal_radius = 0.0;
    const SurfaceSamples as_given = surface_samples(input, options);
    CHECK(as_given.points.normals == input.point_set.points.normals);
    CHECK(as_given.warnings.empty());
  }
  SUBCASE("a spread too wide for the neighbour index is an error naming the file") {
    SurfaceInput far;
    far.path = "far.xyz";
    for (const double x : {0.0, 1.0, 2.0, 1e15})
      far.point_set.points.add(Vec<3>(x, 0.0, 0.0), Vec<3>(0.0, 0.0, 1.0));
    far.point_set.has_normals = true;
    options.normal_radius = 1e-3;
    CHECK_THROWS_WITH_AS(surface_samples(far, options),
                         doctest::Contains("far.xyz: cannot check the normals against their neighbours'"),
                         std::runtime_error);
  }
}
