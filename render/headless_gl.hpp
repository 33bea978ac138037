#pragma once
// One kind of headless OpenGL 3.3 core context (render/egl_context.cpp,
// render/osmesa_context.cpp), as OffscreenContext (render/offscreen_context.cpp) uses
// them: each made by its open_* function, which throws std::runtime_error saying why it
// could not. The colour buffer it draws into is RGBA8 with 24-bit depth and 8-bit stencil,
// bound as the draw and read framebuffer whenever the context is current.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/gl.hpp"
#include "render/headless_gl_choice.hpp"

namespace amls {

class HeadlessGl {
 public:
  virtual ~HeadlessGl() = default;
  // Makes the context current on this thread; throws std::runtime_error if it cannot.
  virtual void make_current() = 0;
  // Where glad finds the GL functions of this context.
  virtual GLADloadfunc gl_loader() const = 0;
  // Once, current and with the GL functions loaded: makes the framebuffer to draw into
  // where the context has none of its own. Throws std::runtime_error if it cannot.
  virtual void prepare_framebuffer(int /*width*/, int /*height*/) {}
  virtual HeadlessBackend backend() const = 0;
  // Which device, for egl-device; else empty.
  virtual std::string device() const { return {}; }
};

// Each EGL device's extension string, in eglQueryDevicesEXT's order. Throws
// std::runtime_error if libEGL cannot list devices.
std::vector<std::string> list_egl_device_extensions();
// EGL_EXT_platform_device: the devices in egl_device_order's order (or only `chosen`), the
// first that gives a 3.3 core context. The error lists each device tried and why it failed.
std::unique_ptr<HeadlessGl> open_egl_device(std::optional<int> chosen);
// EGL_MESA_platform_surfaceless.
std::unique_ptr<HeadlessGl> open_egl_surfaceless();
// OSMesa with its own colour buffer of width x height.
std::unique_ptr<HeadlessGl> open_osmesa(int width, int height);

}  // namespace amls
