// Splat throughput on the current machine's headless OpenGL (the first line says which:
// backend, device, GL_VERSION, GL_RENDERER): frame time and splats per second for a sphere of
// 100k and 1M points (or the sizes given) at 1280x800, framed to fit (default splat size), alone,
// with normals, and with back faces culled.
//   amls_render_bench [frames [points...]]   (default 10 timed frames per size; 100000 1000000)
//   AMLS_GL_BACKEND=egl-device|egl-surfaceless|osmesa, AMLS_EGL_DEVICE=N choose the OpenGL.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numbers>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "render/gl.hpp"
#include "render/offscreen_context.hpp"
#include "render/splat_renderer.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Mean seconds per frame over `frames` frames, each finished (glFinish) before the clock stops.
double time_frames(const amls::SplatRenderer& renderer, const amls::Camera& camera, const amls::Viewport& viewport,
                   const amls::RenderOptions& options, int frames) {
  renderer.draw(camera, viewport, options);  // warm-up: llvmpipe compiles the shaders' variants on first use
  glFinish();
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    renderer.draw(camera, viewport, options);
    glFinish();
  }
  return seconds_since(start) / frames;
}

}  // namespace

int main(int argc, char** argv) try {
  const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 10;
  std::vector<std::size_t> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::stoul(argv[i]));
  if (sizes.empty()) sizes = {100'000, 1'000'000};
  const amls::Viewport viewport{0, 0, 1280, 800};
  amls::OffscreenContext context(viewport.width, viewport.height);
  for (const std::string& failure : context.info().failures)
    std::printf("amls_render_bench: OpenGL backend failed: %s\n", failure.c_str());
  std::printf("amls_render_bench: %s, %dx%d, %d frames per row\n", context.info().summary().c_str(), viewport.width,
              viewport.height, frames);
  std::printf("%10s %11s %9s %10s %11s %12s %14s\n", "splats", "estimate s", "upload s", "frame ms", "splats/s",
              "+normals ms", "cull back ms");
  amls::SplatRenderer renderer;
  for (const std::size_t count : sizes) {
    const amls::PointSet<3> sphere = amls::sample_sphere(amls::Vec<3>::Zero(), 1.0, count);
    Clock::time_point start = Clock::now();
    renderer.set_points(sphere);  // spacing estimated from the points
    const double estimate_and_upload = seconds_since(start);
    const double spacing = renderer.spacing();
    start = Clock::now();
    renderer.set_points(sphere, spacing);  // spacing given: the upload alone
    const double upload = seconds_since(start);

    amls::Camera camera = amls::Camera::orbit();
    camera.fit(renderer.bounds(), viewport.aspect());
    camera.orbit_by(30.0f, 20.0f);
    amls::RenderOptions options;
    const double frame = time_frames(renderer, camera, viewport, options, frames);
    options.show_normals = true;
    const double with_normals = time_frames(renderer, camera, viewport, options, frames);
    options.show_normals = false;
    options.cull_back_faces = true;
    const double culled = time_frames(renderer, camera, viewport, options, frames);
    std::printf("%10zu %11.3f %9.3f %10.1f %11.3g %12.1f %14.1f\n", count, estimate_and_upload - upload, upload,
                1e3 * frame, static_cast<double>(count) / frame, 1e3 * with_normals, 1e3 * culled);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_render_bench: %s\n", e.what());
  return 1;
}
