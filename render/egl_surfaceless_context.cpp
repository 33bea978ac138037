// The egl-surfaceless kind of headless context: Mesa's EGL_MESA_platform_surfaceless,
// where Mesa itself picks the renderer (a GPU's render node, else llvmpipe).
#include "render/egl_context.hpp"

namespace amls {

std::unique_ptr<HeadlessGl> open_egl_surfaceless() {
  EGLDisplay display =
      egl_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, "EGL_MESA_platform_surfaceless");
  return make_egl_context(display, HeadlessBackend::egl_surfaceless, "");
}

}  // namespace amls
