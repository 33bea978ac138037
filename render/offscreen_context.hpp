#pragma once
// A headless OpenGL 3.3 core context drawing into an RGBA8 colour buffer with 24-bit depth
// and 8-bit stencil, of a given size, no display needed. It is the first of the backends
// render/headless_gl_choice.hpp orders (EGL on a device, GPUs first; EGL surfaceless; OSMesa
// where built) that gives one, or the one chosen (AMLS_GL_BACKEND, AMLS_EGL_DEVICE, or a
// program's options). info() says which it got.
//
// glad keeps one table of GL functions for the whole program: each context loads it when
// it is made current after another one was, so several may be used in turn on one thread.
#include <memory>
#include <string>
#include <vector>

#include "render/headless_gl_choice.hpp"
#include "render/render_options.hpp"

namespace amls {

class OffscreenContext {
 public:
  // Creates the context, makes it current and loads the GL functions (glad). Throws
  // std::invalid_argument for a side outside ranges::kImageSide or a bad choice in the
  // environment or `choice` (a device index not listed), std::runtime_error naming each
  // backend tried and why it failed if none gives a 3.3 core context.
  OffscreenContext(int width, int height);  // the environment's choice
  OffscreenContext(int width, int height, const HeadlessGlChoice& choice);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  void make_current();

  int width() const;
  int height() const;
  Viewport viewport() const { return {0, 0, width(), height()}; }
  // The backend, device, GL_VERSION and GL_RENDERER, and what was tried before.
  const HeadlessGlInfo& info() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The backends this build has, in the order they are tried.
std::vector<HeadlessBackend> headless_backends_built();
// Each EGL device's extension string, in eglQueryDevicesEXT's order (the indices that
// AMLS_EGL_DEVICE takes); empty where the build has no EGL or libEGL cannot list devices.
std::vector<std::string> egl_device_extensions();

}  // namespace amls
