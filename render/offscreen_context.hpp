#pragma once
// A headless OpenGL 3.3 core context: OSMesa (Mesa's llvmpipe), RGBA8 colour,
// 24-bit depth, 8-bit stencil, rendering into memory. The only place that knows
// OSMesa, so that EGL surfaceless (Mesa dropped OSMesa after 25.0) can replace it here.
#include <memory>
#include <string>

#include "render/render_options.hpp"

namespace amls {

class OffscreenContext {
 public:
  // Creates the context, makes it current and loads the GL functions (glad). Throws
  // std::invalid_argument for a side outside ranges::kImageSide, std::runtime_error if OSMesa
  // cannot make a 3.3 core context.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  void make_current();

  int width() const;
  int height() const;
  Viewport viewport() const { return {0, 0, width(), height()}; }
  std::string renderer() const;  // GL_VERSION and GL_RENDERER, e.g. "4.5 (Core Profile) Mesa 22.3.6, llvmpipe"

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace amls
