#pragma once
// What the two EGL kinds of headless context share (render/egl_device_context.cpp,
// render/egl_surfaceless_context.cpp differ only in how they get their display): an OpenGL
// 3.3 core context on an EGL display, current without a surface (EGL_KHR_surfaceless_context;
// a 1x1 pbuffer where the display lacks it), drawing into a framebuffer object of its own, so
// that the image may be as large as GL_MAX_RENDERBUFFER_SIZE (pbuffers are often capped lower).
//
// libEGL is linked for EGL 1.4's core functions; every extension function is looked up
// through eglGetProcAddress (egl_function).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>

#include "render/headless_gl.hpp"

namespace amls {

// "EGL_BAD_MATCH (0x3009)" for eglGetError()'s code now.
std::string egl_error_text();
// Throws std::runtime_error naming the first of `names` that libEGL lacks as a client extension
// (or saying that it found no EGL driver at all).
void require_egl_client_extensions(std::initializer_list<const char*> names);

// An extension function, looked up by name; throws std::runtime_error naming it if EGL lacks it.
template <typename Function>
Function egl_function(const char* name) {
  const auto address = eglGetProcAddress(name);
  if (address == nullptr) throw std::runtime_error(std::string("libEGL has no ") + name);
  return reinterpret_cast<Function>(address);
}

// eglGetPlatformDisplayEXT(platform, native_display) where libEGL has EGL_EXT_platform_base
// and `platform_extension`; throws std::runtime_error naming what is missing or EGL's error.
EGLDisplay egl_platform_display(EGLenum platform, void* native_display, const char* platform_extension);

// Initialises `display` (eglGetPlatformDisplay's) and makes a context on it; the display stays
// initialised until exit (see egl_context.cpp). Throws std::runtime_error saying which step
// failed and EGL's error.
std::unique_ptr<HeadlessGl> make_egl_context(EGLDisplay display, HeadlessBackend backend, std::string device);

}  // namespace amls
