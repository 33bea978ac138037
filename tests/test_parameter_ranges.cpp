#include <doctest/doctest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "core/io/mesh_io.hpp"
#include "core/io/mesh_sampling.hpp"
#include "core/io/surface_samples.hpp"
#include "core/run/flow_test.hpp"
#include "core/run/scene.hpp"
#include "core/surface/amls_surface.hpp"
#include "core/util/parameter_ranges.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// A 2D scene as JSON, with one key replaced or added.
nlohmann::json scene_with(const std::string& key, const nlohmann::json& value) {
  nlohmann::json scene = nlohmann::json::parse(R"({
    "dimension": 2,
    "shape": {"type": "circle", "center": [0, 0], "radius": 1, "points": 250},
    "grid": {"spacing": 0.024}, "radius_factor": 3,
    "deformation": {"kind": "rigid", "alpha": 1},
    "stages": [{"handles": [[1, 0], [0, 1]], "targets": [{"steps": 30, "handles": [[1.5, 0], [0, 1]]}]}]
  })");
  scene[nlohmann::json::json_pointer(key)] = value;
  return scene;
}

std::string scene_error(const nlohmann::json& scene) {
  try {
    scene_from_json(scene, "s.json");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(accepted)";
}

template <typename Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("parameter ranges: the message names the key, the value and the range; NaN is outside every range") {
  CHECK(error_of([] { check_range("--radius-factor", 3e-6, ranges::kRadiusFactor); }) ==
        "--radius-factor: must be within [1.5, 32] (the influence radius Delta in units of h), got 3e-06");
  CHECK_NOTHROW(check_range("--radius-factor", 3.0, ranges::kRadiusFactor));
  CHECK_NOTHROW(check_range("--radius-factor", 1.5, ranges::kRadiusFactor));
  CHECK_THROWS_AS(check_range("x", std::numeric_limits<double>::quiet_NaN(), ranges::kAlpha), std::invalid_argument);
  CHECK_THROWS_AS(check_range("x", std::numeric_limits<double>::infinity(), ranges::kSpacing), std::invalid_argument);
}

TEST_CASE("image sizes: one parser for WxH with the one side limit") {
  CHECK(parse_image_size("480x360", "--size").width == 480);
  CHECK(parse_image_size("480X360", "--size").height == 360);
  CHECK(parse_image_size("16384x1", "--size").width == 16384);
  for (const char* bad : {"0x10", "10x0", "480", "480x", "x360", "-4x4", "4x4x4", "16385x10", "4.5x4", " 4x4", "4x4 "})
    CHECK_THROWS_WITH_AS(parse_image_size(bad, "--size"),
                         doctest::Contains("--size: expected WIDTHxHEIGHT with each side a whole number within [1, 16384]"),
                         std::invalid_argument);
  CHECK_THROWS_WITH_AS(parse_image_size("63x600", "--size", 64), doctest::Contains("within [64, 16384]"),
                       std::invalid_argument);
}

TEST_CASE("scene: a radius factor outside the range is refused before any work (it used to hang)") {
  CHECK(scene_error(scene_with("/radius_factor", 3e-06)) ==
        "s.json: radius_factor: must be within [1.5, 32] (the influence radius Delta in units of h), got 3e-06");
  CHECK(scene_error(scene_with("/radius_factor", 100)).find("radius_factor: must be within [1.5, 32]") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/radius_factor", 2)) == "(accepted)");
}

TEST_CASE("scene: every numeric key has its range") {
  CHECK(scene_error(scene_with("/deformation/alpha", 50)).find("deformation.alpha: must be within [0.1, 10]") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/grid", {{"cells", 100000}})).find("grid.cells: must be within [1, 65536]") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/grid", {{"spacing", 1e12}})).find("grid.spacing: must be within [1e-09, 1e+09]") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/shape/points", 2)).find("shape.points: must be within [3, 2e+07] (points), got 2") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/shape/points", 100000000)).find("shape.points: must be within [3, 2e+07]") !=
        std::string::npos);
  CHECK(scene_error(scene_with("/stages/0/targets/0/steps", 1000000)).find("stages[0].targets[0].steps: must be within [1, 100000]") !=
        std::string::npos);
  // Many targets, each within range, still bound the whole run.
  nlohmann::json many = scene_with("/stages/0/targets/0/steps", 100000);
  for (int k = 0; k < 10; ++k) many["stages"][0]["targets"].push_back(many["stages"][0]["targets"][0]);
  CHECK(scene_error(many).find("stages: must be within [1, 1e+06] (steps in all stages), got 1.1e+06") != std::string::npos);
  nlohmann::json handles = nlohmann::json::array();
  for (int k = 0; k < 1025; ++k) handles.push_back({k, 0});
  nlohmann::json crowded = scene_with("/stages/0/handles", handles);
  crowded["stages"][0]["targets"][0]["handles"] = handles;
  CHECK(scene_error(crowded).find("stages[0].handles: must be within [1, 1024] (handles in a stage), got 1025") !=
        std::string::npos);
}

TEST_CASE("scene: a shape that would make too many points is refused, naming a spacing that fits") {
  const std::string message = scene_error(scene_with("/grid", {{"spacing", 1e-7}}));
  CHECK(message.find("s.json: shape: sampling this circle at spacing 1e-07 and resampling it at h = 1e-07 makes about "
                     "6.28319e+07 points, more than 2e+07; a spacing and h of 3.14159e-07 or more would fit") !=
        std::string::npos);
  nlohmann::json sphere = scene_with("/dimension", 3);
  sphere["shape"] = {{"type", "sphere"}, {"radius", 1}, {"spacing", 1e-4}};
  sphere["stages"][0] = nlohmann::json::parse(R"({"handles": [[1, 0, 0]], "targets": [{"steps": 1, "handles": [[1, 0, 0]]}]})");
  CHECK(scene_error(sphere).find("shape: sampling this sphere at spacing 0.0001") != std::string::npos);
}

TEST_CASE("scene: a non-finite number anywhere is refused with its key") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(scene_error(scene_with("/stages/0/targets/0/handles/1/0", inf)) ==
        "s.json: stages[0].targets[0].handles[1][0]: not a finite number");
  // Also where no reader looks: the whole file is checked first.
  CHECK(scene_error(scene_with("/description", nlohmann::json::array({1.0, inf}))) ==
        "s.json: description[1]: not a finite number");
  CHECK(scene_error(scene_with("/radius_factor", std::numeric_limits<double>::quiet_NaN())) ==
        "s.json: radius_factor: not a finite number");
}

TEST_CASE("flow tests and the surface refuse out-of-range parameters with the option's name") {
  FlowTestConfig config;
  config.grid = 128;
  config.radius_factor = 0.000003;
  CHECK(error_of([&] { run_vortex_test(config); }) ==
        "--radius-factor: must be within [1.5, 32] (the influence radius Delta in units of h), got 3e-06");
  config.radius_factor = 3.0;
  config.dt = 0.0;
  CHECK(error_of([&] { run_vortex_test(config); }).find("--dt: must be within [0.0001, 1]") != std::string::npos);
  config.dt = 0.01;
  config.substeps = 0;
  CHECK(error_of([&] { run_vortex_test(config); }).find("--substeps: must be within [1, 1000]") != std::string::npos);
  config.substeps = 1;
  config.grid = 65536;
  CHECK(error_of([&] { run_enright_test(config); }) ==
        "--grid 65536 would start from 4.85749e+09 points, more than 2e+07; use --grid 4205 or less");
  CHECK(error_of([] { AmlsSurface<2>(Grid<2>::unit(64), AmlsParameters{3e-6}); }) ==
        "radius factor: must be within [1.5, 32] (the influence radius Delta in units of h), got 3e-06");
}

TEST_CASE("mesh sampling: a mesh with a stray far vertex is refused at once, naming a spacing that fits") {
  TempDir dir;
  // A cube of side 0.6 whose seventh vertex has a typo (07363029 for 0.7363029).
  write_text(dir.file("typo.obj"),
             "v 0.2 0.2 0.2\nv 0.8 0.2 0.2\nv 0.8 0.8 0.2\nv 0.2 0.8 0.2\nv 0.2 0.2 0.8\nv 0.8 0.2 0.8\n"
             "v 07363029 0.255480 0.607000\nv 0.2 0.8 0.8\n"
             "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n");
  SurfaceSampleOptions options;
  options.spacing = 1.0 / 64;
  options.normal_radius = 3.0 / 64;
  const std::string message = error_of([&] { load_surface_samples(dir.file("typo.obj"), options); });
  CHECK(message.find("typo.obj") != std::string::npos);
  CHECK(message.find("mesh sampling: spacing 0.015625 would make about 4.44123e+17 samples, more than 2e+07 (the mesh "
                     "spans 7.36303e+06 across); a spacing of 2351.68 or more would fit") != std::string::npos);
  // The spacing it names does fit.
  options.spacing = 2351.68;
  options.normal_radius = 3.0 * options.spacing;
  CHECK(load_surface_samples(dir.file("typo.obj"), options).points.size() > 0);
  // The same cube without the typo samples as before.
  TriangleMesh cube = read_mesh(dir.file("typo.obj"));
  cube.vertices[6] = Vec<3>(0.8, 0.8, 0.8);
  CHECK(sample_mesh(cube, 1.0 / 64).points.size() > 1000);
}
