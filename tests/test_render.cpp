// Headless rendering (EGL or OSMesa, render/offscreen_context.hpp): real pixels of real frames.
// Set AMLS_RENDER_TEST_PNG_DIR to a folder to keep every rendered frame as a PNG.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/run/deforming_surface.hpp"
#include "core/geometry/shapes.hpp"
#include "render/headless.hpp"
#include "render/image.hpp"
#include "render/offscreen_context.hpp"
#include "render/point_data.hpp"
#include "render/splat_renderer.hpp"

using namespace amls;

namespace {

constexpr int kSize = 256;
const Viewport kViewport{0, 0, kSize, kSize};

// A context and a renderer for one test; frames are optionally kept as PNGs.
struct Headless {
  OffscreenContext context{kSize, kSize};
  SplatRenderer renderer;

  Image draw(const Camera& camera, const RenderOptions& options = {}, const char* keep_as = nullptr) {
    renderer.draw(camera, kViewport, options);
    Image image = read_framebuffer(kViewport);
    if (const char* dir = std::getenv("AMLS_RENDER_TEST_PNG_DIR"); dir && keep_as)
      write_png(std::filesystem::path(dir) / (std::string(keep_as) + ".png"), image);
    return image;
  }
};

struct Rgb {
  int r, g, b;
};

Rgb rgb_at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

Rgb to_rgb8(const glm::vec3& c) {
  auto unorm = [](float v) { return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return {unorm(c.r), unorm(c.g), unorm(c.b)};
}

bool close(const Rgb& a, const Rgb& b, int tolerance = 1) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}

bool is_background(const Image& image, int x, int y, const RenderOptions& options = {}) {
  return close(rgb_at(image, x, y), to_rgb8(options.background), 0);
}

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

glm::vec3 to_glm(const Vec<3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

// Whether the pixel nearest `window` (x, y from the top-left) or one of its 8 neighbours has `color`.
bool color_near(const Image& image, glm::vec3 window, const glm::vec3& color, int tolerance = 1) {
  const int cx = static_cast<int>(std::floor(window.x)), cy = static_cast<int>(std::floor(window.y));
  for (int y = cy - 1; y <= cy + 1; ++y)
    for (int x = cx - 1; x <= cx + 1; ++x)
      if (x >= 0 && y >= 0 && x < image.width && y < image.height &&
          close(rgb_at(image, x, y), to_rgb8(color), tolerance))
        return true;
  return false;
}

// The unit sphere sampled at about `spacing` (Fibonacci lattice: 4 pi / N per point).
PointSet<3> unit_sphere(double spacing) {
  const auto count = static_cast<std::size_t>(4.0 * std::numbers::pi / (spacing * spacing * std::sqrt(3.0) / 2.0));
  return sample_sphere(Vec<3>::Zero(), 1.0, count);
}

// Looking down -z at the origin from distance 3.5 (the default view direction).
Camera front_camera() {
  Camera camera = Camera::orbit();
  camera.distance = 3.5f;
  camera.scene = {glm::vec3(0.0f), 1.2f};
  return camera;
}

// The radius in pixels of the unit sphere's image for front_camera: the cone from the eye
// touching the sphere has half-angle asin(1 / d); its image radius is tan of that, scaled.
double sphere_image_radius_px(const Camera& camera) {
  const double alpha = std::asin(1.0 / camera.distance);
  const double focal = 1.0 / std::tan(0.5 * glm::radians(static_cast<double>(camera.fov_y_deg)));
  return std::tan(alpha) * focal * 0.5 * kSize;
}

// Options that tell holes apart even where the far side shows through them: back faces
// in pure blue, while front faces (surface colour) always have more red than blue.
RenderOptions hole_revealing_options() {
  RenderOptions options;
  options.back_color = {0.0f, 0.0f, 1.0f};
  return options;
}

struct DiskCoverage {
  std::size_t covered = 0;        // pixels that are not background
  std::size_t holes_inside = 0;   // background or back-face pixels well inside the expected silhouette
  std::size_t stray_outside = 0;  // covered pixels well outside it
};

DiskCoverage disk_coverage(const Image& image, double radius_px, double margin_px) {
  DiskCoverage c;
  const double centre = 0.5 * kSize;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double r = std::hypot(x + 0.5 - centre, y + 0.5 - centre);
      const bool background = is_background(image, x, y);
      const Rgb color = rgb_at(image, x, y);
      const bool back_face = !background && color.b > color.r;
      if (!background) ++c.covered;
      if ((background || back_face) && r < radius_px - margin_px) ++c.holes_inside;
      if (!background && r > radius_px + margin_px) ++c.stray_outside;
    }
  return c;
}

}  // namespace

TEST_CASE("a sampled sphere renders as a closed disk of the expected area at the default splat size") {
  Headless h;
  const double spacing = 0.06;
  const PointUpload upload = h.renderer.set_points(unit_sphere(spacing));  // spacing estimated
  CHECK(upload.skipped == 0);
  CHECK(upload.spacing > 0.8 * spacing);  // the Fibonacci lattice's median gap is a little under the nominal
  CHECK(upload.spacing < spacing);
  const Camera camera = front_camera();
  const Image image = h.draw(camera, hole_revealing_options(), "sphere");

  const double radius_px = sphere_image_radius_px(camera);
  REQUIRE(radius_px > 90.0);
  const DiskCoverage c = disk_coverage(image, radius_px, 1.5);
  CHECK(c.holes_inside == 0);
  CHECK(c.stray_outside == 0);
  const double expected_area = std::numbers::pi * radius_px * radius_px;
  CHECK(static_cast<double>(c.covered) == doctest::Approx(expected_area).epsilon(0.03));
}

TEST_CASE("an orthographic view of the sphere is a closed disk of the sphere's radius") {
  Headless h;
  h.renderer.set_points(unit_sphere(0.06));
  Camera camera = Camera::planar();
  camera.half_height = 1.25f;
  camera.scene = {glm::vec3(0.0f), 1.2f};
  const Image image = h.draw(camera, hole_revealing_options(), "sphere_orthographic");
  const double radius_px = 1.0 / 1.25 * 0.5 * kSize;
  const DiskCoverage c = disk_coverage(image, radius_px, 1.5);
  CHECK(c.holes_inside == 0);
  CHECK(c.stray_outside == 0);
  CHECK(static_cast<double>(c.covered) == doctest::Approx(std::numbers::pi * radius_px * radius_px).epsilon(0.03));
}

TEST_CASE("the side of the sphere facing the headlight is brighter than its rim, and no back face shows") {
  Headless h;
  h.renderer.set_points(unit_sphere(0.06));
  const Camera camera = front_camera();
  RenderOptions options;
  const Image image = h.draw(camera, options);
  const double radius_px = sphere_image_radius_px(camera);
  const int c = kSize / 2;
  const double centre = luminance(rgb_at(image, c, c));
  for (int sign : {-1, 1}) {
    const int rim = c + sign * static_cast<int>(0.93 * radius_px);
    CHECK(centre > luminance(rgb_at(image, rim, c)) + 40.0);
    CHECK(centre > luminance(rgb_at(image, c, rim)) + 40.0);
  }
  // Front faces have the surface colour's hue (red > green > blue); the back colour is reddish.
  const Rgb middle = rgb_at(image, c, c);
  CHECK(middle.r > middle.b);
  CHECK(middle.g > middle.b);
}

TEST_CASE("an AMLS-resampled sphere (gaps up to ~1.5 h) closes at the default splat size with spacing h") {
  const Grid<3> grid = Grid<3>::unit(48);
  DeformingSurface<3> surface(grid, AmlsParameters{}, Variant::exact, 2);
  surface.set_points(sample_sphere(Vec<3>::Zero(), 0.3, 2500));
  surface.resample_only();
  REQUIRE(surface.points().size() > 1000);

  Headless h;
  h.renderer.set_points(surface.points(), grid.spacing());
  Camera camera = Camera::orbit();
  camera.fit(h.renderer.bounds(), 1.0f);
  camera.distance = 3.5f * 0.3f;  // the unit-sphere framing of the other tests, scaled
  for (float azimuth : {0.0f, 37.0f, 121.0f}) {
    camera.azimuth_deg = azimuth;
    camera.elevation_deg = azimuth / 3.0f;
    const std::string name = "resampled_sphere_" + std::to_string(static_cast<int>(azimuth));
    const Image image = h.draw(camera, hole_revealing_options(), name.c_str());
    const double radius_px = std::tan(std::asin(1.0 / 3.5)) / std::tan(glm::radians(20.0)) * 0.5 * kSize;
    CHECK(disk_coverage(image, radius_px, 2.0).holes_inside == 0);
  }
}

TEST_CASE("splat depth is per pixel: two crossing disks each win on their nearer half") {
  Headless h;
  PointSet<3> crossing;
  const double s = std::sqrt(0.5);
  crossing.add(Vec<3>::Zero(), Vec<3>(s, 0.0, s));   // plane z = -x: nearer on the left
  crossing.add(Vec<3>::Zero(), Vec<3>(-s, 0.0, s));  // plane z = x: nearer on the right
  h.renderer.set_points(crossing, 1.0);
  RenderOptions options;
  options.color_mode = ColorMode::normal;  // red = 0.5 + 0.5 n.x tells the disks apart
  options.splat_scale = 0.5f;
  Camera camera = front_camera();
  const Image image = h.draw(camera, options, "crossing_disks");
  const int c = kSize / 2;
  for (int dx : {10, 30}) {
    const Rgb left = rgb_at(image, c - dx, c), right = rgb_at(image, c + dx, c);
    CHECK(left.r > right.r + 60);  // left: the disk with n.x > 0
  }
}

TEST_CASE("a disk seen from behind gets the back-face colour") {
  Headless h;
  PointSet<3> disk;
  disk.add(Vec<3>::Zero(), Vec<3>(0.0, 0.0, -1.0));  // facing away from the default view
  h.renderer.set_points(disk, 1.0);
  RenderOptions options;
  options.back_color = {0.0f, 0.0f, 1.0f};
  const Image image = h.draw(front_camera(), options);
  const Rgb middle = rgb_at(image, kSize / 2, kSize / 2);
  CHECK(middle.b > 200);
  CHECK(middle.r < 70);
  CHECK(middle.g < 70);
}

TEST_CASE("scalar colouring follows the colour ramp from low to high values") {
  Headless h;
  const PointSet<3> sphere = unit_sphere(0.06);
  h.renderer.set_points(sphere);
  std::vector<double> x(sphere.size());
  for (std::size_t i = 0; i < sphere.size(); ++i) x[i] = sphere.positions[i][0];
  h.renderer.set_scalars(x);
  RenderOptions options;
  options.color_mode = ColorMode::scalar;
  const Image image = h.draw(front_camera(), options, "sphere_scalar");
  const int c = kSize / 2;
  const Rgb low = rgb_at(image, c - 60, c), high = rgb_at(image, c + 60, c);
  CHECK(low.b > low.g);    // the ramp's low end is violet-blue
  CHECK(high.g > high.b);  // its high end is green-yellow
  CHECK_THROWS_AS(h.renderer.set_scalars(std::vector<double>(3, 0.0)), std::invalid_argument);
}

TEST_CASE("a 2D circle renders its curve, its points as dots and its normals where they project") {
  Headless h;
  const Vec<2> center(0.5, 0.5);
  const double radius = 0.3;
  const std::size_t n = 64;
  h.renderer.set_points(sample_circle(center, radius, n));
  REQUIRE(h.renderer.spacing() == doctest::Approx(2.0 * std::numbers::pi * radius / n).epsilon(0.01));
  // The curve: a polyline of 256 segments on the circle, shifted half a step from the points.
  std::vector<glm::vec2> segments;
  for (int i = 0; i < 256; ++i)
    for (int k : {i, i + 1}) {
      const double a = 2.0 * std::numbers::pi * (k + 0.5) / 256.0;
      segments.emplace_back(center[0] + radius * std::cos(a), center[1] + radius * std::sin(a));
    }
  h.renderer.set_curve(segments);
  Camera camera = Camera::planar();
  camera.fit(h.renderer.bounds(), 1.0f);
  RenderOptions options;
  options.show_normals = true;
  options.normal_length = 2.0f;
  options.show_grid = true;
  const Image image = h.draw(camera, options, "circle_2d");

  const double h_world = h.renderer.spacing();
  int curve_hits = 0, dot_hits = 0, normal_hits = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const glm::vec3 u(std::cos(a), std::sin(a), 0.0f);
    const glm::vec3 p = glm::vec3(center[0], center[1], 0.0f) + static_cast<float>(radius) * u;
    const double between = a + std::numbers::pi / static_cast<double>(n);  // midway between two points
    const glm::vec3 q(center[0] + radius * std::cos(between), center[1] + radius * std::sin(between), 0.0f);
    curve_hits += color_near(image, camera.to_window(q, kViewport), options.curve_color);
    dot_hits += close(rgb_at(image, static_cast<int>(camera.to_window(p, kViewport).x),
                             static_cast<int>(camera.to_window(p, kViewport).y)),
                      to_rgb8(options.surface_color), 1);
    const glm::vec3 mid = p + 1.2f * static_cast<float>(h_world) * u;  // on the normal, beyond the dot
    normal_hits += color_near(image, camera.to_window(mid, kViewport), options.normal_color);
  }
  CHECK(curve_hits == static_cast<int>(n));
  CHECK(dot_hits >= static_cast<int>(n) - 2);
  CHECK(normal_hits == static_cast<int>(n));
  // The grid (spacing h) shows somewhere in the empty middle of the circle.
  int grid_pixels = 0;
  for (int y = 100; y < 156; ++y)
    for (int x = 100; x < 156; ++x) grid_pixels += close(rgb_at(image, x, y), to_rgb8(options.grid_color), 1);
  CHECK(grid_pixels > 50);
}

TEST_CASE("normals of a 3D point set stick out of the sphere's silhouette along the normal") {
  Headless h;
  const PointSet<3> sphere = unit_sphere(0.06);
  h.renderer.set_points(sphere, 0.06);
  RenderOptions options;
  options.show_normals = true;
  options.normal_length = 4.0f;
  const Camera camera = front_camera();
  const Image image = h.draw(camera, options, "sphere_normals");
  // The points nearest the silhouette's left, right, top and bottom: their normals lie in the image plane.
  int hits = 0;
  for (const Vec<3>& axis : {Vec<3>(1, 0, 0), Vec<3>(-1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, -1, 0)}) {
    std::size_t best = 0;
    for (std::size_t i = 0; i < sphere.size(); ++i)
      if (sphere.positions[i].dot(axis) > sphere.positions[best].dot(axis)) best = i;
    const Vec<3> p = sphere.positions[best] + 0.15 * sphere.normals[best];  // past the splats' overhang
    hits += color_near(image, camera.to_window(to_glm(p), kViewport), options.normal_color);
  }
  CHECK(hits == 4);
}

TEST_CASE("handles are drawn on top, at their projected positions, at a constant pixel size, coloured by state") {
  Headless h;
  h.renderer.set_points(unit_sphere(0.06));
  const std::vector<Handle> handles{{glm::vec3(0.0f, 0.0f, 0.0f), HandleState::idle},  // inside: hidden by depth
                                    {glm::vec3(0.5f, 0.0f, 0.9f), HandleState::hovered},
                                    {glm::vec3(-0.5f, 0.3f, -0.9f), HandleState::selected}};  // behind
  h.renderer.set_handles(handles);
  RenderOptions options;
  const Camera camera = front_camera();
  const Image image = h.draw(camera, options, "handles");
  for (const Handle& handle : handles) {
    const glm::vec3 w = camera.to_window(handle.position, kViewport);
    const glm::vec3 color = options.handle_colors[static_cast<std::size_t>(handle.state)];
    CHECK(close(rgb_at(image, static_cast<int>(w.x), static_cast<int>(w.y)), to_rgb8(color)));
    // Constant pixel size: 14 px across, so 4 px off centre is inside, 10 px off is outside.
    CHECK(close(rgb_at(image, static_cast<int>(w.x) + 4, static_cast<int>(w.y)), to_rgb8(color)));
    CHECK_FALSE(close(rgb_at(image, static_cast<int>(w.x) + 10, static_cast<int>(w.y)), to_rgb8(color), 8));
  }
}

TEST_CASE("the same input renders the same image") {
  const PointSet<3> sphere = unit_sphere(0.05);
  RenderJob job;
  job.width = 200;
  job.height = 120;
  job.camera = Camera::orbit();
  job.camera->azimuth_deg = 30.0f;
  job.camera->elevation_deg = 20.0f;
  job.options.show_normals = true;
  auto fill = [&](SplatRenderer& r) { r.set_points(sphere); };
  const Image a = render_offscreen(job, fill);
  const Image b = render_offscreen(job, fill);
  REQUIRE(a.width == 200);
  REQUIRE(a.height == 120);
  CHECK(a == b);
}

TEST_CASE("render_to_png writes a PNG framed to fit, and bad input gives clear errors") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "amls_render_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path png = dir / "sphere.png";
  std::filesystem::remove(png);
  RenderJob job;
  job.width = 64;
  job.height = 48;
  render_to_png(png, job, unit_sphere(0.1));
  CHECK(std::filesystem::file_size(png) > 100);

  CHECK_THROWS_AS(render_to_png(png, job, PointSet<3>{}), std::invalid_argument);  // empty
  PointSet<3> broken;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  broken.add(Vec<3>(nan, 0, 0), Vec<3>(0, 0, 1));
  broken.add(Vec<3>(0, 0, 0), Vec<3>(nan, 0, 1));
  broken.add(Vec<3>(1, 0, 0), Vec<3>(0, 0, 0));
  CHECK_THROWS_AS(render_to_png(png, job, broken), std::invalid_argument);  // nothing drawable
  RenderJob zero = job;
  zero.width = 0;
  CHECK_THROWS_AS(render_to_png(png, zero, unit_sphere(0.1)), std::invalid_argument);
  CHECK_THROWS_AS(write_png(png, Image{}), std::invalid_argument);
  CHECK_THROWS_AS(write_png(dir / "no_such_folder" / "x.png", Image{1, 1, {0, 0, 0, 255}}), std::runtime_error);
}

TEST_CASE("points with NaN positions or normals are skipped, and scalars stay with their points") {
  Headless h;
  PointSet<3> sphere = unit_sphere(0.06);
  const std::size_t n = sphere.size();
  sphere.positions[5] = Vec<3>::Constant(std::numeric_limits<double>::quiet_NaN());
  sphere.normals[9] = Vec<3>::Zero();
  const PointUpload upload = h.renderer.set_points(sphere);
  CHECK(upload.skipped == 2);
  CHECK(upload.drawn == n - 2);
  CHECK(h.renderer.point_count() == n - 2);
  h.renderer.set_scalars(std::vector<double>(n, 1.0));  // one per input point, skipped ones included
  RenderOptions options;
  options.color_mode = ColorMode::scalar;
  const Image image = h.draw(front_camera(), options);
  CHECK_FALSE(is_background(image, kSize / 2, kSize / 2));

  CHECK_THROWS_AS(h.renderer.draw(front_camera(), Viewport{0, 0, 0, 10}, options), std::invalid_argument);
  CHECK_THROWS_AS(h.renderer.set_points(PointSet<3>{{Vec<3>::Zero()}, {}}), std::invalid_argument);
  CHECK_THROWS_AS(h.renderer.set_points(sphere, -1.0), std::invalid_argument);
  const std::vector<glm::vec3> odd(3, glm::vec3(0.0f));
  CHECK_THROWS_AS(h.renderer.set_curve(odd), std::invalid_argument);
  // An empty point set is allowed in an editor: it draws the background only.
  h.renderer.set_points(PointSet<3>{});
  CHECK(is_background(h.draw(front_camera()), kSize / 2, kSize / 2));
}

TEST_CASE("a renderer made without a current GL context is a clear error") {
  { OffscreenContext made_and_released(8, 8); }  // leaves the GL loader set up, but no context current
  CHECK_THROWS_AS(SplatRenderer{}, std::runtime_error);
}

TEST_CASE("a camera saved as JSON restores the same view - bad JSON names the field") {
  Camera camera = Camera::orbit();
  camera.fit({glm::vec3(1.0f, 2.0f, 3.0f), 0.5f}, 1.6f);
  camera.orbit_by(25.0f, -10.0f);
  camera.pan_by_pixels({12.0f, -7.0f}, Viewport{0, 0, 640, 400});
  camera.zoom_by(1.5f);
  const nlohmann::json saved = camera;
  const Camera restored = nlohmann::json::parse(saved.dump()).get<Camera>();
  CHECK(restored.view() == camera.view());
  CHECK(restored.projection(1.6f) == camera.projection(1.6f));

  nlohmann::json bad = saved;
  bad["distance"] = -1.0;
  CHECK_THROWS_WITH_AS(bad.get<Camera>(), doctest::Contains("distance"), std::invalid_argument);
  bad = saved;
  bad["target"] = "here";
  CHECK_THROWS_WITH_AS(bad.get<Camera>(), doctest::Contains("target"), std::invalid_argument);
  CHECK_THROWS_AS(nlohmann::json::object().get<Camera>(), std::invalid_argument);
  CHECK_THROWS_AS(camera.fit(BoundingSphere{}, 1.0f), std::invalid_argument);
}

TEST_CASE("the default 3D view looks down -z with +y up, and fit frames the bounds") {
  Camera camera = Camera::orbit();
  camera.fit({glm::vec3(0.0f), 1.0f}, 2.0f);
  const glm::vec3 eye = camera.eye();
  CHECK(eye.x == doctest::Approx(0.0));
  CHECK(eye.y == doctest::Approx(0.0));
  CHECK(eye.z > 1.0f);
  const Viewport wide{0, 0, 400, 200};
  const glm::vec3 right = camera.to_window({1.0f, 0.0f, 0.0f}, wide), up = camera.to_window({0.0f, 1.0f, 0.0f}, wide);
  CHECK(right.x > 200.0f);  // +x to the right
  CHECK(up.y < 100.0f);     // +y up (window y grows downwards)
  // The sphere's top touches (almost) the viewport's top edge: the height limits a wide view.
  const float alpha = std::asin(1.0f / camera.distance);  // the cone from the eye touching the sphere
  const glm::vec3 top = camera.to_window({0.0f, 1.0f / std::cos(alpha), 0.0f}, wide);
  const float expected = 100.0f * (1.0f - std::tan(alpha) / std::tan(glm::radians(0.5f * camera.fov_y_deg)));
  CHECK(top.y == doctest::Approx(expected).epsilon(1e-3));
  CHECK(expected > 2.0f);  // a margin is left
}

TEST_CASE("panning moves the scene with the cursor, zooming scales it about the view centre") {
  const Viewport viewport{0, 0, 300, 200};
  for (Camera camera : {Camera::orbit(), Camera::planar()}) {
    camera.fit({glm::vec3(0.5f, -1.0f, 2.0f), 1.0f}, viewport.aspect());
    camera.orbit_by(40.0f, 25.0f);
    const glm::vec3 target = camera.target;
    const glm::vec3 before = camera.to_window(target, viewport);
    camera.pan_by_pixels({30.0f, -12.0f}, viewport);
    const glm::vec3 after = camera.to_window(target, viewport);
    CHECK(after.x - before.x == doctest::Approx(30.0).epsilon(1e-3));
    CHECK(after.y - before.y == doctest::Approx(-12.0).epsilon(1e-3));
    const glm::vec3 centre = camera.target, offset = centre + glm::vec3(0.1f, 0.1f, 0.0f);
    const float span =
        glm::distance(glm::vec2(camera.to_window(offset, viewport)), glm::vec2(camera.to_window(centre, viewport)));
    camera.zoom_by(2.0f);
    const float zoomed =
        glm::distance(glm::vec2(camera.to_window(offset, viewport)), glm::vec2(camera.to_window(centre, viewport)));
    CHECK(zoomed > 1.8f * span);
  }
}

TEST_CASE("the spacing estimate is the median nearest-neighbour distance") {
  const PointSet<3> sphere = sample_sphere(Vec<3>(1.0, 2.0, 3.0), 0.5, 3001);  // < 4096: every point measured
  std::vector<double> nearest(sphere.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < sphere.size(); ++i)
    for (std::size_t j = 0; j < sphere.size(); ++j)
      if (i != j) nearest[i] = std::min(nearest[i], (sphere.positions[i] - sphere.positions[j]).norm());
  std::nth_element(nearest.begin(), nearest.begin() + 1500, nearest.end());
  CHECK(estimate_spacing<3>(sphere.positions) == nearest[1500]);
  const PointSet<2> circle = sample_circle(Vec<2>(3.0, -2.0), 2.0, 500);
  CHECK(estimate_spacing<2>(circle.positions) == doctest::Approx(4.0 * std::numbers::pi / 500).epsilon(1e-6));
  std::vector<Vec<3>> line;
  for (int i = 0; i < 100; ++i) line.emplace_back(0.25 * i, 1e3, 0.0);
  CHECK(estimate_spacing<3>(line) == doctest::Approx(0.25));
  CHECK(estimate_spacing<3>(std::vector<Vec<3>>(5, Vec<3>::Ones())) == 0.0);
}
