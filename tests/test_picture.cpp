// `amls render`'s path (app/picture_input.hpp, app/render_arguments.hpp,
// render/picture.hpp) on small files, rendered headless (EGL or OSMesa).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "app/picture_input.hpp"
#include "app/render_arguments.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/scene.hpp"
#include "render/headless.hpp"
#include "core/geometry/sample_spacing.hpp"
#include "scene_fixtures.hpp"
#include "temp_dir.hpp"

using namespace amls;
using amls::test::pulled_circle;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

const ImageSize kSmall{160, 120};

Image render(const Picture& picture, const std::optional<OrbitView>& view = std::nullopt,
             const RenderOptions& options = {}) {
  return render_offscreen(picture_job(picture, kSmall, view, options),
                          [&](SplatRenderer& renderer) { picture.fill(renderer); });
}

bool is_color(const Image& image, int x, int y, const glm::vec3& color, int tolerance = 1) {
  const std::uint8_t* p = image.pixel(x, y);
  for (int c = 0; c < 3; ++c)
    if (std::abs(p[c] - static_cast<int>(std::lround(color[c] * 255.0f))) > tolerance) return false;
  return true;
}

std::size_t count_color(const Image& image, const glm::vec3& color, int tolerance = 0) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += is_color(image, x, y, color, tolerance);
  return n;
}

}  // namespace

TEST_CASE("render picture: a 3D point set file renders at the asked size, centred, from the default direction") {
  TempDir dir;
  const std::string ply = dir.file("sphere.ply");
  write_point_set(ply, sample_sphere(Vec<3>(2.0, -1.0, 0.5), 0.5, 3000), PointFileFormat::ply_binary_little_endian);
  const Picture picture = load_picture(ply, {});
  CHECK(picture.dimension == 3);
  CHECK(picture.points.size() == 3000);
  CHECK(picture.h > 0.0);
  CHECK(picture.curve.empty());
  const RenderJob job = picture_job(picture, kSmall, std::nullopt, {});
  REQUIRE(job.camera);
  CHECK(job.camera->azimuth_deg == 30.0f);
  CHECK(job.camera->elevation_deg == 20.0f);
  CHECK(job.framing == Framing::keep);  // framed by picture_job on the shape's box
  CHECK(job.camera->target.x == doctest::Approx(2.0).epsilon(0.01));
  CHECK(job.camera->target.y == doctest::Approx(-1.0).epsilon(0.01));

  const RenderOptions options;
  const Image image = render(picture);
  REQUIRE(image.width == 160);
  REQUIRE(image.height == 120);
  CHECK_FALSE(is_color(image, 80, 60, options.background, 0));  // the sphere is centred
  CHECK(is_color(image, 2, 2, options.background, 0));          // and framed with room around it
  CHECK(is_color(image, 157, 117, options.background, 0));
}

TEST_CASE("render picture: --view with a distance keeps it - a farther eye makes a smaller image") {
  TempDir dir;
  const std::string ply = dir.file("sphere.ply");
  write_point_set(ply, sample_sphere(Vec<3>::Zero(), 1.0, 3000), PointFileFormat::ply_binary_little_endian);
  const Picture picture = load_picture(ply, {});
  const RenderOptions options;
  const std::size_t near = 160 * 120 - count_color(render(picture, parse_view("0,0,4")), options.background);
  const std::size_t far = 160 * 120 - count_color(render(picture, parse_view("0,0,8")), options.background);
  const RenderJob job = picture_job(picture, kSmall, parse_view("10,-5,4"), {});
  CHECK(job.camera->distance == 4.0f);
  CHECK(job.camera->elevation_deg == -5.0f);
  // Image area falls with the square of the distance (roughly: perspective).
  CHECK(static_cast<double>(near) / static_cast<double>(far) == doctest::Approx(4.0).epsilon(0.15));
}

TEST_CASE("render picture: a 2D point set shows its MLS curve on the circle, between dots that do not hide it") {
  TempDir dir;
  const std::string xyz = dir.file("circle.xyz");
  const Vec<2> center(0.5, 0.5);
  write_point_set(xyz, sample_circle(center, 0.3, 120), PointFileFormat::xyz);
  PictureInputOptions input;
  input.spacing = 1.0 / 128.0;
  const Picture picture = load_picture(xyz, input);
  CHECK(picture.dimension == 2);
  CHECK(picture.h == 1.0 / 128.0);
  REQUIRE(picture.curve.size() > 200);
  CHECK(picture.curve.size() % 2 == 0);
  for (const glm::vec2& p : picture.curve) CHECK(std::abs(glm::length(p - glm::vec2(0.5f)) - 0.3f) < 2e-3f);
  const RenderJob job = picture_job(picture, kSmall, std::nullopt, {});
  CHECK(job.camera->mode == Camera::Mode::planar);
  CHECK(job.options.point_size_px >= 1.5f);
  CHECK(job.options.point_size_px <= 7.0f);
  const Image image = render(picture);
  CHECK(count_color(image, RenderOptions{}.curve_color, 8) > 100);
  CHECK_THROWS_AS(picture_job(picture, kSmall, parse_view("30,20"), {}), std::invalid_argument);

  input.curve = false;
  CHECK(load_picture(xyz, input).curve.empty());
}

TEST_CASE("render picture: a point set without normals gets estimated ones, and quality is per point in units of h") {
  TempDir dir;
  const std::string xyz = dir.file("bare.xyz");
  std::string text;
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 2000);
  for (const Vec<3>& p : sphere.positions)
    text += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  write_text(xyz, text);
  PictureInputOptions input;
  input.quality = true;
  const Picture picture = load_picture(xyz, input);
  REQUIRE(picture.points.size() == 2000);
  for (std::size_t i = 0; i < picture.points.size(); i += 97)  // oriented outwards
    CHECK(picture.points.normals[i].dot(picture.points.positions[i]) > 0.9);
  REQUIRE(picture.quality.size() == 2000);
  // h was chosen by the rule of core/geometry/sample_spacing.hpp: the median quality
  // is the median nearest-neighbour distance in units of that h.
  const SampleSpacing rule = sample_spacing<3>(picture.points.positions);
  CHECK(picture.h == rule.h);
  std::vector<double> sorted = picture.quality;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted[1000] == doctest::Approx(rule.nearest_median / rule.h).epsilon(0.01));
  RenderOptions options;
  options.color_mode = ColorMode::scalar;
  const RenderJob job = picture_job(picture, kSmall, std::nullopt, options);
  REQUIRE(job.options.scalar_range);
  CHECK(job.options.scalar_range->x == 0.3f);
  CHECK(job.options.scalar_range->y == 1.5f);
  const Image image = render(picture, std::nullopt, options);
  CHECK_FALSE(is_color(image, 80, 60, options.background, 0));
}

TEST_CASE("render picture: a triangle mesh is sampled at its diagonal / 200 with face normals") {
  TempDir dir;
  const std::string obj = dir.file("tetra.obj");
  write_text(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const Picture picture = load_picture(obj, {});
  CHECK(picture.dimension == 3);
  CHECK(picture.h == doctest::Approx(std::sqrt(3.0) / 200.0));
  CHECK(picture.points.size() > 1000);
  CHECK_FALSE(is_color(render(picture), 80, 60, RenderOptions{}.background, 0));
}

TEST_CASE("render picture: a scene at step K, with its handles and its curve - 'last' is its whole history") {
  TempDir dir;
  const std::string json = dir.file("pulled.json");
  write_scene(json, pulled_circle(3));
  PictureInputOptions input;
  input.step = kFinalStep;
  const Picture last = load_picture(json, input);
  CHECK(last.dimension == 2);
  CHECK(last.h == 0.024);
  REQUIRE(last.handles.size() == 4);
  CHECK(glm::length(last.handles[0]) == doctest::Approx(1.3));
  CHECK(last.curve.size() > 200);
  CHECK(last.description.find("after 3 of 3 steps") != std::string::npos);
  input.step = 0;
  const Picture first = load_picture(json, input);
  CHECK(glm::length(first.handles[0]) == doctest::Approx(1.0));
  const RenderOptions options;
  const Image image = render(last);
  CHECK(count_color(image, options.handle_colors[0], 1) > 4 * 20);  // four handles of 14 px
  CHECK(count_color(image, options.curve_color, 8) > 100);

  input.step = 4;
  CHECK_THROWS_AS(load_picture(json, input), std::invalid_argument);  // past the end
  input.step = std::nullopt;
  input.spacing = 0.01;
  CHECK_THROWS_AS(load_picture(json, input), std::invalid_argument);  // a scene has its own h
}

TEST_CASE("render picture: bad input gives a clear error, never a crash") {
  TempDir dir;
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  // An empty point set.
  const std::string empty = dir.file("empty.xyz");
  write_text(empty, "# nothing here\n");
  CHECK(message([&] { load_picture(empty, {}); }).find("no points") != std::string::npos);
  // A NaN normal.
  const std::string nan_normal = dir.file("nan.xyz");
  write_text(nan_normal, "0 0 0 0 0 1\n1 0 0 nan 0 1\n0 1 0 0 0 1\n");
  const std::string nan_message = message([&] { load_picture(nan_normal, {}); });
  CHECK(nan_message.find("nan.xyz") != std::string::npos);
  CHECK(nan_message.find("normal") != std::string::npos);
  // Missing files, and a step for a file.
  CHECK_THROWS_AS(load_picture(dir.file("missing.ply"), {}), std::runtime_error);
  PictureInputOptions step;
  step.step = 1;
  CHECK_THROWS_AS(load_picture(nan_normal, step), std::invalid_argument);
  // Views and colour modes (sizes: test_parameter_ranges.cpp).
  CHECK(parse_view("30,20").distance == std::nullopt);
  CHECK(*parse_view("-45,10.5,3").distance == 3.0f);
  for (const char* bad : {"", "30", "30,", "a,b", "30,95", "30,20,0", "30,20,-1", "30,20,3,4", "nan,0", "30,inf"})
    CHECK_THROWS_AS(parse_view(bad), std::invalid_argument);
  CHECK_THROWS_AS(color_mode_from_string("rainbow"), std::invalid_argument);
  // A zero-size image.
  TempDir out;
  write_point_set(dir.file("ok.ply"), sample_sphere(Vec<3>::Zero(), 1.0, 500),
                  PointFileFormat::ply_binary_little_endian);
  const Picture picture = load_picture(dir.file("ok.ply"), {});
  RenderJob job = picture_job(picture, kSmall, std::nullopt, {});
  job.width = 0;
  CHECK_THROWS_AS(render_to_png(out.file("x.png"), job, [&](SplatRenderer& r) { picture.fill(r); }),
                  std::invalid_argument);
  CHECK(out.entries() == 0);
}

TEST_CASE("render picture: supersampling keeps the size and inner colours and blends the silhouette") {
  TempDir dir;
  write_point_set(dir.file("s.ply"), sample_sphere(Vec<3>::Zero(), 1.0, 3000),
                  PointFileFormat::ply_binary_little_endian);
  const Picture picture = load_picture(dir.file("s.ply"), {});
  RenderJob job = picture_job(picture, kSmall, std::nullopt, {});
  const Image sharp = render_offscreen(job, [&](SplatRenderer& r) { picture.fill(r); });
  job.supersample = 3;
  const Image smooth = render_offscreen(job, [&](SplatRenderer& r) { picture.fill(r); });
  REQUIRE(smooth.width == 160);
  REQUIRE(smooth.height == 120);
  const RenderOptions options;
  CHECK(is_color(smooth, 2, 2, options.background, 0));
  for (int c = 0; c < 3; ++c) CHECK(std::abs(smooth.pixel(80, 60)[c] - sharp.pixel(80, 60)[c]) <= 6);
  // Along the middle row the silhouette's edge pixels are mixtures: neither background nor
  // as bright as the sphere there, and there are more distinct values than without.
  auto distinct_reds = [](const Image& image) {
    std::vector<int> reds;
    for (int x = 0; x < image.width; ++x) reds.push_back(image.pixel(x, 60)[0]);
    std::sort(reds.begin(), reds.end());
    return std::unique(reds.begin(), reds.end()) - reds.begin();
  };
  CHECK(distinct_reds(smooth) >= distinct_reds(sharp));
  job.supersample = 0;
  CHECK_THROWS_AS(render_offscreen(job, [&](SplatRenderer& r) { picture.fill(r); }), std::invalid_argument);
  job.supersample = 9;
  CHECK_THROWS_AS(render_offscreen(job, [&](SplatRenderer& r) { picture.fill(r); }), std::invalid_argument);
}
