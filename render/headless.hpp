#pragma once
// Headless rendering in one call: a fresh OffscreenContext, a SplatRenderer, a
// camera framed to the scene, one frame read back as an image or written as PNG.
#include <filesystem>
#include <functional>
#include <optional>

#include "render/camera.hpp"
#include "render/headless_gl_choice.hpp"
#include "render/image.hpp"
#include "render/splat_renderer.hpp"

namespace amls {

enum class Framing {
  fit,     // look at the scene's centre from the camera's direction, at a distance (zoom) that frames it
  center,  // look at the scene's centre, keeping the camera's distance (zoom)
  keep,    // the camera as given
};

struct RenderJob {
  int width = 800;
  int height = 600;
  // None: Camera::planar() for a 2D point set, else Camera::orbit() (looking down -z).
  std::optional<Camera> camera;
  Framing framing = Framing::fit;
  RenderOptions options;
  // Anti-aliasing: the frame is drawn `supersample` times larger in each direction (pixel
  // sizes in `options` scaled alike) and each output pixel is the mean of its s x s block.
  // 1 draws directly, so that every pixel has an exact colour. From 1 to 8.
  int supersample = 1;
  // Which headless OpenGL to draw with; none: the environment's choice (AMLS_GL_BACKEND, AMLS_EGL_DEVICE).
  std::optional<HeadlessGlChoice> gl;
};

// `fill` puts the scene into the renderer (points, scalars, curve, handles). Throws
// std::invalid_argument for a bad size or supersampling factor, or an empty scene; see OffscreenContext and
// SplatRenderer for the rest. `gl_used`, if given, receives which OpenGL drew the image.
Image render_offscreen(const RenderJob& job, const std::function<void(SplatRenderer&)>& fill,
                       HeadlessGlInfo* gl_used = nullptr);
// Returns which OpenGL drew the image.
HeadlessGlInfo render_to_png(const std::filesystem::path& png, const RenderJob& job,
                             const std::function<void(SplatRenderer&)>& fill);

// A point set alone. Throws std::invalid_argument if it is empty or no point is drawable.
template <int D>
HeadlessGlInfo render_to_png(const std::filesystem::path& png, const RenderJob& job, const PointSet<D>& points,
                             std::optional<double> spacing = std::nullopt);

}  // namespace amls
