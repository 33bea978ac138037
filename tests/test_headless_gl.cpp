// Headless OpenGL: which backend and EGL device are tried in which order (pure, no GL), and
// that EGL on Mesa's software device draws the very same bytes as OSMesa (both llvmpipe).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "render/headless.hpp"
#include "render/headless_gl_choice.hpp"
#include "render/image.hpp"
#include "render/offscreen_context.hpp"
#include "render/splat_renderer.hpp"

using namespace amls;

namespace {

using enum HeadlessBackend;
using Order = std::vector<HeadlessBackend>;

const char* const kSoftware = "EGL_MESA_device_software EGL_EXT_device_drm_render_node";
const char* const kDrmGpu = "EGL_EXT_device_drm EGL_EXT_device_drm_render_node";
const char* const kNvidiaGpu = "EGL_NV_device_cuda EGL_EXT_device_drm EGL_EXT_device_persistent_id";

// Mesa's software device's index in eglQueryDevicesEXT's list, if it lists one.
std::optional<int> software_egl_device() {
  const std::vector<std::string> devices = egl_device_extensions();
  for (std::size_t i = 0; i < devices.size(); ++i)
    if (is_software_egl_device(devices[i])) return static_cast<int>(i);
  return std::nullopt;
}

bool built(HeadlessBackend backend) {
  for (HeadlessBackend b : headless_backends_built())
    if (b == backend) return true;
  return false;
}

// A sphere of 1,500 splats seen at an angle, with its normals, a quality ramp, a ring of
// line segments round it and two handles: every pass the renderer has (points, lines, dots).
RenderJob every_pass_job(const HeadlessGlChoice& gl) {
  Camera camera = Camera::orbit();
  camera.azimuth_deg = 30.0f;
  camera.elevation_deg = 20.0f;
  RenderOptions options;
  options.show_normals = true;
  options.color_mode = ColorMode::scalar;
  return {.width = 160, .height = 120, .camera = camera, .options = options, .gl = gl};
}

void fill_every_pass(SplatRenderer& renderer) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 1500);
  renderer.set_points(sphere);
  std::vector<double> quality(sphere.size());
  for (std::size_t i = 0; i < quality.size(); ++i) quality[i] = 0.5 + sphere.positions[i][1];
  renderer.set_scalars(quality);
  std::vector<glm::vec3> ring;
  for (int k = 0; k < 48; ++k)
    for (int end = 0; end < 2; ++end) {
      const double angle = 2.0 * std::numbers::pi * (k + end) / 48.0;
      ring.emplace_back(1.3f * static_cast<float>(std::cos(angle)), 0.0f, 1.3f * static_cast<float>(std::sin(angle)));
    }
  renderer.set_curve(ring);
  const std::vector<Handle> handles = {{glm::vec3(0.0f, 1.0f, 0.0f), HandleState::selected},
                                       {glm::vec3(1.0f, 0.0f, 0.0f), HandleState::idle}};
  renderer.set_handles(handles);
}

std::size_t differing_pixels(const Image& a, const Image& b) {
  std::size_t count = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4)
    if (a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2] ||
        a.rgba[i + 3] != b.rgba[i + 3])
      ++count;
  return count;
}

std::size_t pixels_unlike(const Image& image, const glm::vec3& background) {
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const float c[3] = {background.r, background.g, background.b};
      for (int k = 0; k < 3; ++k)
        if (std::abs(p[k] - std::lround(c[k] * 255.0f)) > 1) {
          ++count;
          break;
        }
    }
  return count;
}

}  // namespace

TEST_CASE("headless backends: EGL on a device, EGL surfaceless, then OSMesa; a chosen one alone") {
  const Order all = {egl_device, egl_surfaceless, osmesa};
  CHECK(headless_backend_order({}, all) == all);
  CHECK(headless_backend_order({}, {osmesa, egl_surfaceless}) == Order{egl_surfaceless, osmesa});
  CHECK(headless_backend_order({}, {egl_device, egl_surfaceless}) == Order{egl_device, egl_surfaceless});
  CHECK(headless_backend_order({egl_surfaceless, std::nullopt}, all) == Order{egl_surfaceless});
  CHECK(headless_backend_order({osmesa, std::nullopt}, all) == Order{osmesa});
  // A device index means the egl-device backend, forced or not.
  CHECK(headless_backend_order({std::nullopt, 2}, all) == Order{egl_device});
  CHECK(headless_backend_order({egl_device, 0}, all) == Order{egl_device});
  CHECK_THROWS_WITH_AS(headless_backend_order({osmesa, 1}, all), doctest::Contains("EGL device 1"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(headless_backend_order({osmesa, std::nullopt}, {egl_device, egl_surfaceless}),
                       doctest::Contains("AMLS_WITH_OSMESA=OFF"), std::runtime_error);
  CHECK_THROWS_WITH_AS(headless_backend_order({egl_device, std::nullopt}, {osmesa}),
                       doctest::Contains("AMLS_WITH_EGL=OFF"), std::runtime_error);
  CHECK_THROWS_AS(headless_backend_order({}, {}), std::runtime_error);
}

TEST_CASE("EGL devices: GPUs first in the order listed, Mesa's software device last, or the one chosen") {
  CHECK(egl_device_order({kSoftware, kDrmGpu, kNvidiaGpu}, std::nullopt) == std::vector<int>{1, 2, 0});
  CHECK(egl_device_order({kNvidiaGpu, kSoftware, kDrmGpu}, std::nullopt) == std::vector<int>{0, 2, 1});
  CHECK(egl_device_order({kSoftware}, std::nullopt) == std::vector<int>{0});
  CHECK(egl_device_order({}, std::nullopt).empty());
  // The software device is chosen like any other, by its index.
  CHECK(egl_device_order({kDrmGpu, kSoftware}, 1) == std::vector<int>{1});
  CHECK_THROWS_WITH_AS(egl_device_order({kDrmGpu, kSoftware}, 2),
                       doctest::Contains("are 2 EGL devices (indices 0 to 1)"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(egl_device_order({}, 0), doctest::Contains("no EGL devices"), std::invalid_argument);
  // Whole words only: a longer extension that starts alike is not the software one.
  CHECK_FALSE(is_software_egl_device("EGL_MESA_device_software_x EGL_EXT_device_drm"));
  CHECK(is_software_egl_device("EGL_EXT_device_drm EGL_MESA_device_software"));
  CHECK_FALSE(has_extension("", "EGL_EXT_device_drm"));
  CHECK_FALSE(has_extension("EGL_EXT_device_drm_render_node", "EGL_EXT_device_drm"));
  CHECK(has_extension("EGL_EXT_device_drm_render_node EGL_EXT_device_drm", "EGL_EXT_device_drm"));
}

TEST_CASE("AMLS_GL_BACKEND and AMLS_EGL_DEVICE: names and indices only, a bad value names the variable") {
  const HeadlessGlChoice none = headless_gl_choice_from(nullptr, nullptr);
  CHECK_FALSE(none.backend);
  CHECK_FALSE(none.egl_device);
  CHECK(headless_gl_choice_from("osmesa", nullptr).backend == osmesa);
  CHECK(headless_gl_choice_from("egl-surfaceless", "").backend == egl_surfaceless);
  const HeadlessGlChoice device = headless_gl_choice_from("auto", "12");
  CHECK_FALSE(device.backend);
  CHECK(device.egl_device == 12);
  CHECK_FALSE(headless_gl_choice_from("", nullptr).backend);
  CHECK_THROWS_WITH_AS(headless_gl_choice_from("opengl", nullptr), doctest::Contains("AMLS_GL_BACKEND: 'opengl'"),
                       std::invalid_argument);
  for (const char* bad : {"-1", "1x", " 1", "1024", "99999"})
    CHECK_THROWS_WITH_AS(headless_gl_choice_from(nullptr, bad), doctest::Contains("AMLS_EGL_DEVICE"),
                         std::invalid_argument);
  CHECK(egl_device_index_from_string("1023", "--egl-device") == 1023);
  CHECK_THROWS_WITH_AS(egl_device_index_from_string("two", "--egl-device"), doctest::Contains("--egl-device: 'two'"),
                       std::invalid_argument);
}

TEST_CASE("EGL on Mesa's software device and OSMesa draw the same bytes (both llvmpipe)") {
  if (!built(osmesa) || !built(egl_device)) {
    MESSAGE("skipped: this build lacks " << std::string(built(osmesa) ? "EGL" : "OSMesa")
                                          << " (AMLS_WITH_EGL, AMLS_WITH_OSMESA)");
    return;
  }
  const std::optional<int> software = software_egl_device();
  if (!software) {
    MESSAGE("skipped: libEGL lists no Mesa software device (EGL_MESA_device_software)");
    return;
  }
  HeadlessGlInfo egl_used;
  HeadlessGlInfo osmesa_used;
  const Image through_egl = render_offscreen(every_pass_job({egl_device, software}), fill_every_pass, &egl_used);
  const Image through_osmesa =
      render_offscreen(every_pass_job({osmesa, std::nullopt}), fill_every_pass, &osmesa_used);
  CHECK(egl_used.backend == egl_device);
  CHECK(egl_used.device.find("software") != std::string::npos);
  CHECK(osmesa_used.backend == osmesa);
  CHECK(egl_used.gl_renderer.find("llvmpipe") != std::string::npos);
  CHECK(egl_used.gl_renderer == osmesa_used.gl_renderer);
  // Not an empty frame: the sphere and its ring cover well over a tenth of the image.
  REQUIRE(pixels_unlike(through_egl, RenderOptions{}.background) > 160 * 120 / 10);
  CHECK(differing_pixels(through_egl, through_osmesa) == 0);
  CHECK(through_egl == through_osmesa);
}

TEST_CASE("each headless backend built gives what it was asked for, and draws as the others on the same renderer") {
  const std::optional<int> software = software_egl_device();
  std::optional<Image> reference;  // the first llvmpipe frame
  std::string reference_renderer;
  for (HeadlessBackend backend : headless_backends_built()) {
    CAPTURE(to_string(backend));
    HeadlessGlChoice choice{backend, std::nullopt};
    if (backend == egl_device) choice.egl_device = software;  // llvmpipe where listed, else the first GPU
    HeadlessGlInfo used;
    const Image image = render_offscreen(every_pass_job(choice), fill_every_pass, &used);
    CHECK(used.backend == backend);
    CHECK(used.failures.empty());
    CHECK_FALSE(used.gl_version.empty());
    CHECK(used.summary().find(to_string(backend)) == 0);
    if (!reference) {
      reference = image;
      reference_renderer = used.gl_renderer;
    } else if (used.gl_renderer == reference_renderer) {
      CHECK(image == *reference);
    } else {
      MESSAGE(std::string(to_string(backend)) << " draws on " << used.gl_renderer << ", not " << reference_renderer
                                 << ": its pixels are not compared");
    }
  }
}

TEST_CASE("contexts of different backends used in turn each draw into their own buffer") {
  if (!built(osmesa) || !built(egl_device) || !software_egl_device()) {
    MESSAGE("skipped: needs both OSMesa and an EGL software device in this build and on this machine");
    return;
  }
  const RenderJob job = every_pass_job({egl_device, software_egl_device()});
  const Image expected = render_offscreen(job, fill_every_pass);
  const Viewport viewport{0, 0, job.width, job.height};
  Camera camera = *job.camera;

  OffscreenContext egl(job.width, job.height, {egl_device, software_egl_device()});
  std::optional<SplatRenderer> egl_renderer(std::in_place);
  fill_every_pass(*egl_renderer);
  camera.fit(egl_renderer->bounds(), viewport.aspect());
  OffscreenContext mesa(job.width, job.height, {osmesa, std::nullopt});
  std::optional<SplatRenderer> mesa_renderer(std::in_place);
  fill_every_pass(*mesa_renderer);

  // Each switch reloads glad's functions for the context made current.
  egl.make_current();
  egl_renderer->draw(camera, viewport, job.options);
  const Image from_egl = read_framebuffer(viewport);
  mesa.make_current();
  mesa_renderer->draw(camera, viewport, job.options);
  const Image from_osmesa = read_framebuffer(viewport);
  mesa_renderer.reset();  // GL objects go while their own context is current
  egl.make_current();
  egl_renderer.reset();
  CHECK(from_egl == expected);
  CHECK(from_osmesa == expected);
}

TEST_CASE("a headless context that cannot be had is a clear error") {
  if (built(egl_device))
    CHECK_THROWS_WITH_AS(OffscreenContext(8, 8, {std::nullopt, 1023}),
                         doctest::Contains("EGL device 1023 was chosen, but there"), std::invalid_argument);
  else
    CHECK_THROWS_WITH_AS(OffscreenContext(8, 8, {std::nullopt, 1023}), doctest::Contains("AMLS_WITH_EGL=OFF"),
                         std::runtime_error);
  if (!built(osmesa))
    CHECK_THROWS_WITH_AS(OffscreenContext(8, 8, {osmesa, std::nullopt}), doctest::Contains("AMLS_WITH_OSMESA=OFF"),
                         std::runtime_error);
  CHECK_THROWS_AS(OffscreenContext(0, 8, {}), std::invalid_argument);
}
