#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/shape_opening.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// The samples of a unit sphere with z on the given side of `cut` (above: a cap; below: a bowl).
PointSet<3> sphere_part(std::size_t sphere_points, double cut, bool above) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points);
  PointSet<3> part;
  for (std::size_t i = 0; i < sphere.size(); ++i)
    if ((sphere.positions[i].z() > cut) == above) part.add(sphere.positions[i], sphere.normals[i]);
  return part;
}

// `points` without their normals, written as text columns x y z.
void write_bare(const std::string& path, const PointSet<3>& points) {
  PointSet<3> bare = points;
  bare.normals.clear();
  write_point_set(path, bare, PointFileFormat::xyz);
}

// How many of `opened`'s normals point the other way from `exact`'s.
std::size_t flipped(const PointSet<3>& opened, const PointSet<3>& exact) {
  REQUIRE(opened.size() == exact.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) count += opened.normals[i].dot(exact.normals[i]) < 0.5 ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("opening a scan without normals: normals estimated and oriented outward, h as amls resample chooses it") {
  TempDir dir;
  ThreadPool pool(2);
  // A cap's highest point is inside it, a bowl's on its rim: both come out on the convex side.
  for (const bool above : {true, false}) {
    CAPTURE(above);
    const PointSet<3> exact = sphere_part(8000, above ? 0.3 : -0.3, above);
    const std::string path = dir.file(above ? "cap.xyz" : "bowl.xyz");
    write_bare(path, exact);
    std::vector<std::string> steps;
    ShapeOpening options;
    options.step = [&](const char* name, int index, int count) {
      CHECK(index == static_cast<int>(steps.size()));
      CHECK(count == kShapeOpeningSteps);
      steps.push_back(name);
    };
    const OpenedShape opened = open_shape_file(path, options, pool);
    CHECK(steps == std::vector<std::string>{"reading the file", "choosing h", "estimating normals"});
    CHECK(opened.dimension == 3);
    CHECK(opened.file_points == exact.size());
    CHECK(opened.source.find("normals estimated") != std::string::npos);
    CHECK(flipped(opened.points, exact) == 0);
    // The command line's h: the rule on the file's points.
    const SpacingChoice rule = choose_spacing(exact.positions, PointSetResampling{});
    CHECK(opened.spacing.h == rule.h);
    CHECK(opened.spacing.reason == rule.reason);
  }
}

TEST_CASE("opening a scan whose normals are unoriented: estimate_normals sets them aside and estimates them") {
  TempDir dir;
  ThreadPool pool(2);
  // Every normal along +z or -z by the point's x, as a scanner that gives no sign would: half of
  // them point inward, in patches as wide as the shape, which no local mending turns back.
  const PointSet<3> exact = sphere_part(8000, 0.3, true);
  PointSet<3> unoriented = exact;
  for (std::size_t i = 0; i < unoriented.size(); ++i)
    if (unoriented.positions[i].x() < 0.0) unoriented.normals[i] = -unoriented.normals[i];
  const std::string path = dir.file("unoriented.xyz");
  write_point_set(path, unoriented, PointFileFormat::xyz);
  ShapeOpening options;
  const OpenedShape given = open_shape_file(path, options, pool);
  CHECK(flipped(given.points, exact) > exact.size() / 4);
  options.estimate_normals = true;
  const OpenedShape estimated = open_shape_file(path, options, pool);
  CHECK(flipped(estimated.points, exact) == 0);
  CHECK(estimated.source.find("with normals, set aside; normals estimated") != std::string::npos);
  // The same points and normals as the file without its normals gives.
  write_bare(dir.file("bare.xyz"), unoriented);
  const OpenedShape bare = open_shape_file(dir.file("bare.xyz"), options, pool);
  CHECK(estimated.points.positions == bare.points.positions);
  CHECK(estimated.points.normals == bare.points.normals);
  CHECK(estimated.spacing.h == bare.spacing.h);
}

TEST_CASE("opening a file: a given spacing wins, a recorded one comes next, and the cost is checked") {
  TempDir dir;
  ThreadPool pool(1);
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 2000);
  const std::string path = dir.file("s.ply");
  write_point_set(path, sphere, PointFileFormat::ply_binary_little_endian, 0.07);
  ShapeOpening options;
  CHECK(open_shape_file(path, options, pool).spacing.h == 0.07);
  CHECK(open_shape_file(path, options, pool).spacing.reason.find("records") != std::string::npos);
  options.resampling.spacing = 0.1;
  const OpenedShape given = open_shape_file(path, options, pool);
  CHECK(given.spacing.h == 0.1);
  CHECK(given.source.find("with normals") != std::string::npos);
  options.resampling.spacing = 1e-6;
  CHECK_THROWS_WITH_AS(open_shape_file(path, options, pool), doctest::Contains("s.ply: h = 1e-06 would give about"),
                       std::invalid_argument);
  options.resampling.spacing = 0.0;
  write_point_set(dir.file("few.xyz"), sample_sphere(Vec<3>::Zero(), 1.0, 4), PointFileFormat::xyz);
  CHECK_THROWS_WITH_AS(open_shape_file(dir.file("few.xyz"), options, pool),
                       doctest::Contains("few.xyz: cannot choose h: measuring the spacing needs more than 4 points"),
                       std::invalid_argument);
}

TEST_CASE("opening a file stops when the pool's check says so") {
  TempDir dir;
  write_bare(dir.file("cap.xyz"), sphere_part(3000, 0.3, true));
  ThreadPool pool(1);
  int polls = 0;
  // Stops at the third step: after reading and choosing h.
  CancelScope stop(pool, [&] { return ++polls > 2; });
  CHECK_THROWS_AS(open_shape_file(dir.file("cap.xyz"), ShapeOpening{}, pool), Cancelled);
  CHECK(polls == 3);
}

TEST_CASE("opening a mesh of a few vertices: h from its size, as too few vertices give no spacing") {
  TempDir dir;
  ThreadPool pool(1);
  // A tetrahedron of side 1 (4 vertices, wound outward) and a unit square (4 vertices, open).
  write_text(dir.file("tetra.off"), "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  write_text(dir.file("square.off"), "OFF\n4 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 1 2 3\n");
  const OpenedShape tetra = open_shape_file(dir.file("tetra.off"), ShapeOpening{}, pool);
  // A closed polyhedron: its mean thickness 3V/A over 16 bounds the longest side over 32.
  const double area = 1.5 + std::sqrt(3.0) / 2.0;
  CHECK(tetra.spacing.h == doctest::Approx(3.0 * (1.0 / 6.0) / area / 16.0));
  CHECK(tetra.spacing.reason.find("its 4 vertices are too few to measure a spacing on") != std::string::npos);
  CHECK(tetra.points.size() > 1000);
  const OpenedShape square = open_shape_file(dir.file("square.off"), ShapeOpening{}, pool);
  CHECK(square.spacing.h == doctest::Approx(1.0 / 32.0));
  // Four vertices in one place have no size to take h from.
  write_text(dir.file("point.off"), "OFF\n4 2 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n3 0 1 2\n3 0 2 3\n");
  CHECK_THROWS_WITH_AS(open_shape_file(dir.file("point.off"), ShapeOpening{}, pool),
                       (dir.file("point.off") + ": cannot choose h: the mesh's 4 vertices all lie at one position").c_str(),
                       std::invalid_argument);
}
