#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/scene.hpp"
#include "core/run/scene_run.hpp"
#include "core/util/file_error.hpp"
#include "tests/scene_errors.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

const char* kGood2d = R"({
  "dimension": 2, "name": "t",
  "shape": {"type": "circle", "center": [0.5, 0.5], "radius": 0.25, "points": 100},
  "grid": {"cells": 64}, "radius_factor": 2.5, "widen_support": true, "variant": "interpolated",
  "deformation": {"kind": "similarity", "alpha": 1.5},
  "stages": [
    {"handles": [[0.75, 0.5], [0.25, 0.5]],
     "targets": [{"steps": 3, "handles": [[0.8, 0.5], [0.25, 0.5]]}, {"steps": 2, "handles": [[0.8, 0.6], [0.2, 0.5]]}]},
    {"handles": [[0.5, 0.75]], "targets": [{"steps": 4, "handles": [[0.5, 0.8]]}]}
  ]
})";

// The message a scene (JSON text, or a file named in it) is rejected with.
std::string error_of(const std::string& text, const TempDir& dir) { return amls::test::scene_error_of(text, dir); }

// kGood2d with one edit: `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  return amls::test::edited_text(kGood2d, from, to);
}

}  // namespace

TEST_CASE("scene: a good scene is read with every field, and written back to the same scene") {
  TempDir dir;
  write_text(dir.file("scene.json"), kGood2d);
  const AnyScene any = read_scene(dir.file("scene.json"));
  REQUIRE(std::holds_alternative<Scene<2>>(any));
  const Scene<2>& s = std::get<Scene<2>>(any);
  CHECK(s.shape.type == ShapeType::circle);
  CHECK(s.shape.points == 100);
  CHECK(s.h() == 1.0 / 64);
  CHECK(s.radius_factor == 2.5);
  CHECK(s.widen_support);
  CHECK(s.parameters().widen_support);
  CHECK(s.variant == Variant::interpolated);
  CHECK(s.kind == MlsKind::similarity);
  CHECK(s.alpha == 1.5);
  CHECK(s.history.stages.size() == 2);
  CHECK(s.history.total_steps() == 9);
  write_scene(dir.file("again.json"), s);
  const Scene<2> again = std::get<Scene<2>>(read_scene(dir.file("again.json")));
  CHECK(to_json(again) == to_json(s));
  CHECK(again.history.stages[0].targets[1].handles[1] == Vec<2>(0.2, 0.5));
}

TEST_CASE("scene: every 3D built-in shape and a file shape relative to the scene") {
  TempDir dir;
  write_text(dir.file("points.xyz"), "0 0 1 0 0 1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 -1 0 0 -1\n");
  write_text(dir.file("tetra.OFF"), "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string stages =
      R"("stages": [{"handles": [[0, 0, 1]], "targets": [{"steps": 1, "handles": [[0, 0, 1.1]]}]}])";
  for (const std::string shape :
       {R"({"type": "sphere", "radius": 0.5, "spacing": 0.1})",
        R"({"type": "torus", "major_radius": 1, "minor_radius": 0.3})",
        R"({"type": "rounded_box", "half_extents": [1, 0.5, 0.5], "radius": 0.2})",
        R"({"type": "file", "path": "points.xyz"})", R"({"type": "file", "path": "tetra.OFF"})"}) {
    write_text(dir.file("s.json"),
               R"({"dimension": 3, "grid": {"spacing": 0.1}, "shape": )" + shape + ", " + stages + "}");
    const AnyScene any = read_scene(dir.file("s.json"));
    REQUIRE(std::holds_alternative<Scene<3>>(any));
    const SceneShapeSamples<3> samples = sample_scene_shape(std::get<Scene<3>>(any), 4.0);
    CHECK(samples.points.size() >= 4);
    CHECK(samples.tracers.size() >= samples.points.size());
  }
}

TEST_CASE("scene: bad scenes are rejected with a message naming the file and what is wrong") {
  TempDir dir;
  CHECK(error_of(edited("\"variant\"", "\"variants\""), dir) ==
        dir.file("scene.json") +
            ": variants: unknown key (expected dimension, name, description, grid, shape, "
            "radius_factor, widen_support, variant, deformation, regions or stages)");
  CHECK(error_of(edited("\"widen_support\": true", "\"widen_support\": 1"), dir) ==
        dir.file("scene.json") + ": widen_support: expected true or false, got 1");
  CHECK(
      error_of(edited("\"type\": \"circle\"", "\"type\": \"square\""), dir)
          .find("shape.type: unknown shape 'square' (expected circle, ellipse, sphere, torus, rounded_box or file)") !=
      std::string::npos);
  CHECK(error_of(edited("\"radius\": 0.25", "\"radius\": \"big\""), dir)
            .find("shape.radius: expected a number, got a string") != std::string::npos);
  CHECK(error_of(edited("[[0.8, 0.6], [0.2, 0.5]]", "[[0.8, 0.6]]"), dir)
            .find("stages[0].targets[1].handles: 1 handles, but the stage has 2 (adding or removing a handle starts a "
                  "new stage)") != std::string::npos);
  CHECK(error_of(edited("[0.5, 0.8]", "[0.5, 0.8, 0]"), dir)
            .find("stages[1].targets[0].handles[0]: expected an array of 2 numbers") != std::string::npos);
  CHECK(error_of(edited("\"steps\": 4", "\"steps\": 0"), dir)
            .find("stages[1].targets[0].steps: must be within [1, 100000] (steps), got 0") != std::string::npos);
  CHECK(error_of(edited("\"steps\": 4", "\"steps\": 2.5"), dir)
            .find("stages[1].targets[0].steps: expected a whole number") != std::string::npos);
  CHECK(error_of(edited("\"alpha\": 1.5", "\"alpha\": NaN"), dir).find("scene.json: not valid JSON") !=
        std::string::npos);
  CHECK(error_of(edited("\"alpha\": 1.5", "\"alpha\": 1e999"), dir)
            .find("not valid JSON: [json.exception.out_of_range.406] number overflow parsing '1e999'") !=
        std::string::npos);
  CHECK(error_of(edited("\"kind\": \"similarity\"", "\"kind\": \"bendy\""), dir)
            .find("deformation.kind: unknown deformation kind 'bendy' (expected affine, similarity or rigid)") !=
        std::string::npos);
  CHECK(error_of(edited("\"type\": \"circle\"", "\"type\": \"sphere\""), dir)
            .find("shape.type: a sphere is a 3D shape, but the scene's dimension is 2") != std::string::npos);
  CHECK(error_of(edited("{\"cells\": 64}", "{\"cells\": 64, \"spacing\": 0.1}"), dir).find("grid: give exactly one") !=
        std::string::npos);
  CHECK(error_of(edited("\"dimension\": 2", "\"dimension\": 4"), dir)
            .find("dimension: must be within [2, 3] (the dimension), got 4") != std::string::npos);
  CHECK(error_of(
            edited("\"shape\": {\"type\": \"circle\", \"center\": [0.5, 0.5], \"radius\": 0.25, \"points\": 100},", ""),
            dir)
            .find("missing the required key 'shape'") != std::string::npos);
  CHECK(error_of(edited("{\"type\": \"circle\", \"center\": [0.5, 0.5], \"radius\": 0.25, \"points\": 100}",
                        "{\"type\": \"file\", \"path\": \"nowhere.ply\"}"),
                 dir)
            .find("shape.path: no such file: " + dir.file("nowhere.ply")) != std::string::npos);
  CHECK_THROWS_WITH_AS(read_scene(dir.file("missing.json")),
                       doctest::Contains("missing.json: cannot open the scene file"), FileError);
  std::filesystem::create_directory(dir.file("folder.json"));
  CHECK_THROWS_WITH_AS(read_scene(dir.file("folder.json")), doctest::Contains("folder.json: is a directory"),
                       FileError);
}

TEST_CASE("scene: a file shape's own normals set aside and estimated with \"normals\": \"estimated\"") {
  TempDir dir;
  // A sphere whose normals all point inward: consistent with each other, so no mending turns them,
  // but wrong, as a scanner's that gives no sign can be.
  PointSet<3> inward = sample_sphere(Vec<3>::Zero(), 1.0, 2000);
  for (Vec<3>& normal : inward.normals) normal = -normal;
  write_point_set(dir.file("inward.xyz"), inward, PointFileFormat::xyz);
  const std::string stages =
      R"(, "stages": [{"handles": [[0, 0, 1]], "targets": [{"steps": 1, "handles": [[0, 0, 1.1]]}]}]})";
  auto scene_with = [&](const std::string& normals) {
    write_text(dir.file("s.json"), R"({"dimension": 3, "grid": {"spacing": 0.1}, "shape": {"type": "file", )"
                                   R"("path": "inward.xyz")" + normals + "}" + stages);
    return std::get<Scene<3>>(read_scene(dir.file("s.json")));
  };
  auto outward = [](const PointSet<3>& points) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) count += points.normals[i].dot(points.positions[i]) > 0.9 ? 1 : 0;
    return count;
  };
  for (const std::string given : {"", R"(, "normals": "given")"}) {
    const Scene<3> scene = scene_with(given);
    CHECK_FALSE(scene.shape.estimate_normals);
    CHECK(outward(sample_scene_shape(scene, 0.0).points) == 0);
    CHECK_FALSE(to_json(scene)["shape"].contains("normals"));  // scenes written before the key read the same
  }
  const Scene<3> estimated = scene_with(R"(, "normals": "estimated")");
  CHECK(estimated.shape.estimate_normals);
  const SceneShapeSamples<3> samples = sample_scene_shape(estimated, 0.0);
  REQUIRE(samples.points.size() == inward.size());
  CHECK(outward(samples.points) == inward.size());
  CHECK(samples.source.find("with normals, set aside; normals estimated") != std::string::npos);
  // Written back, the choice is kept.
  CHECK(to_json(estimated)["shape"]["normals"] == "estimated");
  write_scene(dir.file("again.json"), estimated);
  CHECK(std::get<Scene<3>>(read_scene(dir.file("again.json"))).shape.estimate_normals);

  CHECK(error_of(R"({"dimension": 3, "grid": {"spacing": 0.1}, "shape": {"type": "file", "path": "inward.xyz", )"
                 R"("normals": "guessed"})" + stages, dir)
            .find(R"(shape.normals: expected "given" or "estimated", got "guessed")") != std::string::npos);
  CHECK(error_of(R"({"dimension": 3, "grid": {"spacing": 0.1}, "shape": {"type": "sphere", )"
                 R"("normals": "estimated"})" + stages, dir)
            .find("shape.normals: unknown key") != std::string::npos);
}

TEST_CASE("scene: a shape file with no points is named when the shape is sampled") {
  TempDir dir;
  write_text(dir.file("empty.xyz"), "# amls dim 2\n");
  write_text(dir.file("s.json"),
             edited("{\"type\": \"circle\", \"center\": [0.5, 0.5], \"radius\": 0.25, \"points\": 100}",
                    "{\"type\": \"file\", \"path\": \"empty.xyz\"}"));
  const Scene<2> scene = std::get<Scene<2>>(read_scene(dir.file("s.json")));
  CHECK_THROWS_WITH_AS(sample_scene_shape(scene, 1.0), doctest::Contains("empty.xyz: holds no points"),
                       std::runtime_error);
}

TEST_CASE("scene: a file shape without a grid takes h from the file's points; other shapes need a grid") {
  TempDir dir;
  // 200 points on a circle of radius 1 in the plane, as x y nx ny lines (the 4th neighbour two steps away).
  std::string points;
  for (int i = 0; i < 200; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / 200;
    points += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0 " + std::to_string(std::cos(a)) +
              " " + std::to_string(std::sin(a)) + " 0\n";
  }
  write_text(dir.file("circle.xyz"), points);
  write_text(dir.file("scene.json"),
             R"({"dimension": 2, "shape": {"type": "file", "path": "circle.xyz"})"
             R"(, "stages": [{"handles": [[1, 0]], "targets": [{"steps": 1, "handles": [[1.1, 0]]}]}]})");
  const AnyScene any = read_scene(dir.file("scene.json"));
  const Scene<2>& s = std::get<Scene<2>>(any);
  CHECK(s.grid_from_file);
  CHECK(s.h() == doctest::Approx(2.0 * 3.141592653589793 / 200).epsilon(1e-3));

  CHECK(error_of(R"({"dimension": 2, "shape": {"type": "circle"})"
                 R"(, "stages": [{"handles": [[1, 0]], "targets": [{"steps": 1, "handles": [[1.1, 0]]}]}]})",
                 dir)
            .find("missing the required key 'grid' (only a file shape may leave it out") != std::string::npos);
  write_text(dir.file("two.xyz"), "0 0 0 1 0 0\n1 0 0 1 0 0\n");
  CHECK(error_of(R"({"dimension": 2, "shape": {"type": "file", "path": "two.xyz"})"
                 R"(, "stages": [{"handles": [[1, 0]], "targets": [{"steps": 1, "handles": [[1.1, 0]]}]}]})",
                 dir)
            .find("shape.path: no 'grid' given, and h cannot be measured on the file") != std::string::npos);
}
