#include <doctest/doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "app/editor/edit_session.hpp"
#include "app/editor/initial_shape.hpp"
#include "app/editor/scene_start.hpp"
#include "app/editor/session_recording.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/scene_run.hpp"
#include "core/run/shape_opening.hpp"
#include "editor_test_support.hpp"

using namespace amls;
using namespace amls::editor;
using amls::test::write_text;

namespace {

// A scene with the given dimension and shape object, h = 0.05 and one stage of one handle.
std::string scene_text(int dimension, const std::string& shape) {
  const std::string handle = dimension == 2 ? "[1, 0]" : "[1, 0, 0]";
  const std::string target = dimension == 2 ? "[1.2, 0]" : "[1.2, 0, 0]";
  return "{\"dimension\": " + std::to_string(dimension) + ", \"shape\": " + shape +
         ", \"grid\": {\"spacing\": 0.05}, \"stages\": [{\"handles\": [" + handle +
         "], \"targets\": [{\"steps\": 1, \"handles\": [" + target + "]}]}]}";
}

// The start has the scene's shape as its source and the points the core samples from it.
template <int D>
void check_start(const InitialShape& start, const Scene<D>& scene) {
  REQUIRE(std::holds_alternative<SceneShape<D>>(start.source));
  Scene<D> as_started = scene;
  as_started.shape = std::get<SceneShape<D>>(start.source);
  CHECK(to_json(as_started)["shape"] == to_json(scene)["shape"]);
  CHECK(as_started.shape.resolved_file == scene.shape.resolved_file);
  const PointSet<D> expected = sample_scene_shape(scene, 0.0).points;
  REQUIRE(start.points.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    CHECK(start.points.positions[i].template head<D>() == expected.positions[i]);
}

}  // namespace

TEST_CASE("built-in shapes: the paper's circle and a sphere, with their scene sources") {
  const InitialShape circle = default_shape(2);
  CHECK(circle.dimension() == 2);
  CHECK(circle.points.size() == 250);
  CHECK(circle.name == "circle of 250 points");
  REQUIRE(std::holds_alternative<SceneShape<2>>(circle.source));
  CHECK(std::get<SceneShape<2>>(circle.source).type == ShapeType::circle);
  CHECK(std::get<SceneShape<2>>(circle.source).points == 250);
  CHECK(circle.settings.spacing == 0.024);
  CHECK_FALSE(circle.settings.widen_support);  // the paper's shapes keep one Delta
  const InitialShape sphere = make_sphere(2.0, 500, 0.1);
  CHECK(sphere.dimension() == 3);
  CHECK(std::get<SceneShape<3>>(sphere.source).type == ShapeType::sphere);
  CHECK(sphere.points.positions[7].norm() == doctest::Approx(2.0));
  CHECK_THROWS_AS(make_circle(1.0, 2, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(make_circle(-1.0, 20, 0.1), std::invalid_argument);
}

TEST_CASE("a shape of 100,000 points or more resamples under local in the editor, a smaller one as the paper") {
  CHECK(default_shape(3).settings.policy.kind == ResamplePolicy::Kind::always);
  CHECK(make_sphere(1.0, kLocalResamplingFrom - 1, 0.01).settings.policy.kind == ResamplePolicy::Kind::always);
  const InitialShape large = make_sphere(1.0, kLocalResamplingFrom, 0.01);
  CHECK(large.settings.policy.kind == ResamplePolicy::Kind::local);
  CHECK(EditSession<3>(large, 1).settings().policy.kind == ResamplePolicy::Kind::local);
}

TEST_CASE("a point-set file opens with h from its spacing, and the coverage of one resampling at h") {
  amls::test::TempDir dir;
  const std::string path = dir.file("circle.ply");
  write_point_set(path, sample_circle(Vec<2>(0.5, 0.5), 0.25, 200), PointFileFormat::ply_binary_little_endian);
  const InitialShape shape = load_initial_shape(path, 1);
  CHECK(shape.dimension() == 2);
  CHECK(shape.points.size() == 200);
  const SceneShape<2>& source = std::get<SceneShape<2>>(shape.source);
  CHECK(source.type == ShapeType::file);
  CHECK(source.resolved_file == path);
  CHECK(shape.settings.spacing == doctest::Approx(2.0 * 3.14159265 * 0.25 / 200).epsilon(0.01));
  CHECK(shape.settings.widen_support);
  CHECK(shape.coverage == "resampled at h: 100.00 % of the 200 input points covered, 100.00 % of the " +
                              std::to_string(resample_point_set(to_2d(shape.points),
                                                                [&] {
                                                                  PointSetResampling o;
                                                                  o.spacing = shape.settings.spacing;
                                                                  return o;
                                                                }())
                                                 .points.size()) +
                              " output points on the input, 0.00 % in gaps");
  CHECK_FALSE(shape.coverage_loss);
}

TEST_CASE("a point-set file whose resampling at h loses a part says so") {
  amls::test::TempDir dir;
  // A dense circle sets h; a sparse one far away (10 points, 40 Delta apart:
  // beyond what a widened support, at most 4 Delta, bridges) is lost at that
  // h: 10 of 410 points.
  PointSet<2> points = sample_circle(Vec<2>(0.0, 0.0), 1.0, 400);
  const PointSet<2> sparse = sample_circle(Vec<2>(10.0, 0.0), 3.0, 10);
  for (std::size_t i = 0; i < sparse.size(); ++i) points.add(sparse.positions[i], sparse.normals[i]);
  const std::string path = dir.file("two.ply");
  write_point_set(path, points, PointFileFormat::ply_binary_little_endian);
  const InitialShape shape = load_initial_shape(path, 1);
  CHECK(shape.coverage_loss);
  CHECK(shape.coverage.find("two.ply: the output misses part of the input: 10 of 410 input points") !=
        std::string::npos);
}

TEST_CASE("a point-set file without normals opens as amls resample opens it: normals estimated, the same h") {
  amls::test::TempDir dir;
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.2, 0.0, -0.1), 1.0, 3000);
  PointSet<3> bare = sphere;
  bare.normals.clear();
  const std::string path = dir.file("bare.xyz");
  write_point_set(path, bare, PointFileFormat::xyz);
  std::vector<int> steps;
  ThreadPool pool(2);
  const InitialShape shape = load_initial_shape(path, pool, [&](const char*, int index, int count) {
    CHECK(count == kShapeOpeningSteps + 1);
    steps.push_back(index);
  });
  CHECK(steps == std::vector<int>{0, 1, 2, 3});
  CHECK(shape.dimension() == 3);
  REQUIRE(shape.points.size() == sphere.size());
  std::size_t outward = 0;
  for (std::size_t i = 0; i < sphere.size(); ++i)
    outward += shape.points.normals[i].dot(sphere.normals[i]) > 0.9 ? 1 : 0;
  CHECK(outward == sphere.size());
  // The command line's h, to the editor's 3 significant digits.
  const double rule = choose_spacing(sphere.positions, PointSetResampling{}).h;
  CHECK(shape.settings.spacing == doctest::Approx(rule).epsilon(0.005));
  CHECK(shape.opened.find("normals estimated") != std::string::npos);
  CHECK(shape.opened.find("4th nearest neighbour") != std::string::npos);
  CHECK_FALSE(shape.coverage_loss);
}

TEST_CASE("a file the editor exported opens again at its h, which the file records") {
  amls::test::TempDir dir;
  const std::string path = dir.file("exported.ply");
  write_point_set(path, sample_sphere(Vec<3>::Zero(), 1.0, 3000), PointFileFormat::ply_binary_little_endian, 0.0432);
  CHECK(load_initial_shape(path, 1).settings.spacing == 0.0432);
}

TEST_CASE("a point-set file opened with its normals set aside: estimated as without them, and a saved session replays it") {
  amls::test::TempDir dir;
  // Every normal inward: consistent, so the file's own are kept inward unless set aside.
  PointSet<3> inward = sample_sphere(Vec<3>::Zero(), 1.0, 3000);
  for (Vec<3>& normal : inward.normals) normal = -normal;
  const std::string path = dir.file("inward.ply");
  write_point_set(path, inward, PointFileFormat::ply_binary_little_endian);
  auto outward = [](const PointSet<3>& points) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < points.size(); ++i) count += points.normals[i].dot(points.positions[i]) > 0.9 ? 1 : 0;
    return count;
  };
  ThreadPool pool(2);
  const InitialShape given = load_initial_shape(path, pool);
  CHECK(outward(given.points) == 0);
  CHECK_FALSE(std::get<SceneShape<3>>(given.source).estimate_normals);
  const InitialShape estimated = load_initial_shape(path, pool, {}, true);
  REQUIRE(estimated.points.size() == inward.size());
  CHECK(outward(estimated.points) == inward.size());
  CHECK(estimated.opened.find("with normals, set aside; normals estimated") != std::string::npos);
  REQUIRE(std::holds_alternative<SceneShape<3>>(estimated.source));
  CHECK(std::get<SceneShape<3>>(estimated.source).estimate_normals);

  // h has the 3 digits Save Scene writes (and the normals were estimated with that h) ...
  const double h = estimated.settings.spacing;
  const double scale = std::pow(10.0, 2.0 - std::floor(std::log10(h)));
  CHECK(std::abs(h * scale - std::round(h * scale)) < 1e-6);
  // ... so that Save Scene after one step names the choice, and `amls deform` starts from the same points.
  SessionRecording<3> recording(std::get<SceneShape<3>>(estimated.source), estimated.settings);
  recording.deformed({Vec<3>(0, 0, 1)}, {Vec<3>(0, 0, 1.1)}, estimated.settings);
  recording.resampled(estimated.settings);
  const std::string scene_path = dir.file("session.json");
  write_scene(scene_path, recorded_scene(recording, scene_path, "session"));
  const Scene<3> replayed = std::get<Scene<3>>(read_scene(scene_path));
  CHECK(replayed.shape.estimate_normals);
  const SceneShapeSamples<3> samples = sample_scene_shape(replayed, 0.0, 2);
  CHECK(samples.points.positions == estimated.points.positions);
  CHECK(samples.points.normals == estimated.points.normals);
  // And the editor opens the saved scene with them estimated, whatever its own choice for shape files.
  CHECK(outward(load_initial_shape(scene_path, pool).points) == inward.size());
}

TEST_CASE("a point-set file too small, empty or missing is refused with its name") {
  amls::test::TempDir dir;
  const std::string few = dir.file("few.xyz");
  write_text(few, "0 0 0\n1 0 0\n0 1 0\n");
  CHECK_THROWS_WITH_AS(load_initial_shape(few, 1), doctest::Contains("few.xyz: cannot choose h"),
                       std::invalid_argument);
  write_text(dir.file("empty.xyz"), "# nothing\n");
  CHECK_THROWS_WITH_AS(load_initial_shape(dir.file("empty.xyz"), 1), doctest::Contains("empty.xyz: holds no points"),
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(load_initial_shape(dir.file("missing.ply"), 1), doctest::Contains("missing.ply"),
                       std::runtime_error);
}

TEST_CASE("a scene's start: shape, grid, parameters and the first stage's handles") {
  amls::test::TempDir dir;
  const std::string path = dir.file("s.json");
  write_text(path, R"({"dimension": 2, "name": "clover", "shape": {"type": "circle", "center": [0.5, 0], "radius": 2,
    "points": 100}, "grid": {"cells": 40}, "radius_factor": 2.5, "widen_support": true, "variant": "interpolated",
    "deformation": {"kind": "affine", "alpha": 2}, "stages": [{"handles": [[2.5, 0], [0.5, 2]],
    "targets": [{"steps": 3, "handles": [[3, 0], [0.5, 2]]}]}]})");
  const InitialShape shape = load_initial_shape(path, 1);
  CHECK(shape.name == "clover");
  CHECK(shape.points.size() == 100);
  CHECK(shape.points.positions[0].x() == doctest::Approx(2.5));
  CHECK(std::get<SceneShape<2>>(shape.source).center.x() == 0.5);
  CHECK(shape.settings.spacing == 1.0 / 40);
  CHECK(shape.settings.radius_factor == 2.5);
  CHECK(shape.settings.widen_support);
  CHECK(shape.settings.variant == Variant::interpolated);
  CHECK(shape.settings.kind == MlsKind::affine);
  CHECK(shape.settings.alpha == 2.0);
  REQUIRE(shape.handles.size() == 2);
  CHECK(shape.handles[1].y() == 2.0);
}

TEST_CASE("every shape type of a scene starts from the points amls deform starts from, its source as written") {
  amls::test::TempDir dir;
  write_point_set(dir.file("ring.xyz"), sample_circle(Vec<2>::Zero(), 1.0, 100), PointFileFormat::xyz);
  const std::pair<int, std::string> shapes[] = {
      {2, R"({"type": "circle", "radius": 1})"},
      {2, R"({"type": "ellipse", "center": [0.1, 0], "semi_axes": [1, 0.5]})"},
      {2, R"({"type": "rounded_box", "half_extents": [1, 0.5], "radius": 0.2, "spacing": 0.04})"},
      {2, R"({"type": "file", "path": "ring.xyz"})"},
      {3, R"({"type": "sphere", "radius": 1, "points": 400})"},
      {3, R"({"type": "torus", "major_radius": 1, "minor_radius": 0.3})"},
      {3, R"({"type": "rounded_box", "half_extents": [1, 0.5, 0.5], "radius": 0.25})"},
  };
  for (const auto& [dimension, shape] : shapes) {
    CAPTURE(shape);
    const std::string path = dir.file("s.json");
    write_text(path, scene_text(dimension, shape));
    const InitialShape start = load_initial_shape(path, 1);
    CHECK(start.dimension() == dimension);
    CHECK(start.name == "s.json");
    CHECK(start.settings.spacing == 0.05);
    CHECK(start.handles.size() == 1);
    std::visit([&](const auto& scene) { check_start(start, scene); }, read_scene(path));
  }
}

TEST_CASE("scenes the core reader refuses: its message names the file and the key") {
  amls::test::TempDir dir;
  const std::string path = dir.file("bad.json");
  const std::pair<std::string, std::string> cases[] = {
      {scene_text(2, R"({"type": "circle", "radius": 1, "colour": "red"})"), "bad.json: shape.colour: unknown key"},
      {scene_text(2, R"({"type": "circle", "radius": "one"})"), "bad.json: shape.radius: expected a number"},
      {scene_text(3, R"({"type": "file", "path": "gone.ply"})"), "bad.json: shape.path: no such file"},
      {scene_text(3, R"({"type": "circle"})"), "shape.type: a circle is a 2D shape"},
      {R"({"dimension": 2, "shape": {"type": "circle"}, "grid": {"spacing": 0.1}, "stages": []})",
       "stages: the history has no stage"},
      {"{ not json", "bad.json: not valid JSON"},
  };
  for (const auto& [text, message] : cases) {
    CAPTURE(text);
    write_text(path, text);
    CHECK_THROWS_WITH_AS(load_initial_shape(path, 1), doctest::Contains(message.c_str()), std::runtime_error);
  }
}
