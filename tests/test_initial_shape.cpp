#include <doctest/doctest.h>

#include <fstream>

#include "app/editor/initial_shape.hpp"
#include "app/editor/scene_start.hpp"
#include "core/point_set_io.hpp"
#include "core/shapes.hpp"
#include "editor_test_support.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST_CASE("built-in shapes: the paper's circle and a sphere, with their scene sources") {
  const InitialShape circle = default_shape(2);
  CHECK(circle.dimension == 2);
  CHECK(circle.points.size() == 250);
  CHECK(circle.source.type == ShapeSource::Type::circle);
  CHECK(circle.settings.spacing == 0.024);
  const InitialShape sphere = make_sphere(2.0, 500, 0.1);
  CHECK(sphere.dimension == 3);
  CHECK(sphere.points.positions[7].norm() == doctest::Approx(2.0));
  CHECK_THROWS_AS(make_circle(1.0, 2, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(make_circle(-1.0, 20, 0.1), std::invalid_argument);
}

TEST_CASE("a point-set file opens with h set to its median spacing") {
  amls::test::TempDir dir;
  const std::string path = dir.file("circle.ply");
  write_point_set(path, sample_circle(Vec<2>(0.5, 0.5), 0.25, 200), PointFileFormat::ply_binary_little_endian);
  const InitialShape shape = load_initial_shape(path);
  CHECK(shape.dimension == 2);
  CHECK(shape.points.size() == 200);
  CHECK(shape.source.type == ShapeSource::Type::file);
  CHECK(shape.settings.spacing == doctest::Approx(2.0 * 3.14159265 * 0.25 / 200).epsilon(0.01));
}

TEST_CASE("a point-set file without normals, empty or missing is refused with its name") {
  amls::test::TempDir dir;
  const std::string bare = dir.file("bare.xyz");
  write(bare, "0 0 0\n1 0 0\n0 1 0\n");
  CHECK_THROWS_WITH_AS(load_initial_shape(bare), doctest::Contains("no normals"), std::runtime_error);
  CHECK_THROWS_WITH_AS(load_initial_shape(dir.file("missing.ply")), doctest::Contains("missing.ply"),
                       std::runtime_error);
}

TEST_CASE("a scene's start: shape, grid, parameters and the first stage's handles") {
  amls::test::TempDir dir;
  const std::string path = dir.file("s.json");
  write(path, R"({"dimension": 2, "name": "clover", "shape": {"type": "circle", "center": [0.5, 0], "radius": 2,
    "points": 100}, "grid": {"cells": 40}, "radius_factor": 2.5, "variant": "interpolated",
    "deformation": {"kind": "affine", "alpha": 2}, "stages": [{"handles": [[2.5, 0], [0.5, 2]],
    "targets": [{"steps": 3, "handles": [[3, 0], [0.5, 2]]}]}]})");
  const InitialShape shape = load_initial_shape(path);
  CHECK(shape.name == "clover");
  CHECK(shape.points.size() == 100);
  CHECK(shape.points.positions[0].x() == doctest::Approx(2.5));
  CHECK(shape.source.center.x() == 0.5);
  CHECK(shape.settings.spacing == 1.0 / 40);
  CHECK(shape.settings.radius_factor == 2.5);
  CHECK(shape.settings.variant == Variant::interpolated);
  CHECK(shape.settings.kind == MlsKind::affine);
  CHECK(shape.settings.alpha == 2.0);
  REQUIRE(shape.handles.size() == 2);
  CHECK(shape.handles[1].y() == 2.0);
}

TEST_CASE("a scene's file shape is found relative to the scene") {
  amls::test::TempDir dir;
  write_point_set(dir.file("ring.xyz"), sample_circle(Vec<2>::Zero(), 1.0, 100), PointFileFormat::xyz);
  write(dir.file("s.json"),
        R"({"dimension": 2, "shape": {"type": "file", "path": "ring.xyz"}, "grid": {"spacing": 0.05}, "stages": []})");
  const InitialShape shape = load_initial_shape(dir.file("s.json"));
  CHECK(shape.points.size() == 100);
  CHECK(shape.settings.spacing == 0.05);
  CHECK(shape.source.type == ShapeSource::Type::file);
}

TEST_CASE("scene errors name the file and the key") {
  amls::test::TempDir dir;
  const std::string path = dir.file("bad.json");
  write(path, R"({"dimension": 2, "shape": {"type": "circle"}, "grid": {"cells": 10, "spacing": 0.1}})");
  CHECK_THROWS_WITH_AS(load_scene_start(path), doctest::Contains("bad.json: grid"), std::runtime_error);
  write(path, R"({"dimension": 3, "shape": {"type": "circle"}, "grid": {"cells": 10}})");
  CHECK_THROWS_WITH_AS(load_scene_start(path), doctest::Contains("shape.type"), std::runtime_error);
  write(path, R"({"dimension": 3, "shape": {"type": "torus"}, "grid": {"cells": 10}})");
  CHECK_THROWS_WITH_AS(load_scene_start(path), doctest::Contains("torus"), std::runtime_error);
  write(path, "{ not json");
  CHECK_THROWS_WITH_AS(load_scene_start(path), doctest::Contains("not valid JSON"), std::runtime_error);
}
