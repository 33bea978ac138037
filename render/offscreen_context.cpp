#include "render/offscreen_context.hpp"

#include <stdexcept>
#include <vector>

#include "core/util/parameter_ranges.hpp"

// glad first: it must precede GL/gl.h, which osmesa.h includes (kept in order by hand).
// clang-format off
#include "render/gl.hpp"
#include <GL/osmesa.h>
// clang-format on

namespace amls {

namespace {

GLADapiproc osmesa_proc(const char* name) { return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name)); }

}  // namespace

struct OffscreenContext::State {
  OSMesaContext context = nullptr;
  int width = 0;
  int height = 0;
  std::vector<unsigned char> pixels;  // the colour buffer OSMesa renders into, bottom-up
};

OffscreenContext::OffscreenContext(int width, int height) : state_(std::make_unique<State>()) {
  check_range("offscreen image width", width, ranges::kImageSide);
  check_range("offscreen image height", height, ranges::kImageSide);
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            8,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  state_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (state_->context == nullptr) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
  state_->width = width;
  state_->height = height;
  state_->pixels.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  try {
    make_current();
    if (gladLoadGL(osmesa_proc) == 0) throw std::runtime_error("could not load OpenGL functions through OSMesa");
  } catch (...) {
    OSMesaDestroyContext(state_->context);
    throw;
  }
}

OffscreenContext::~OffscreenContext() {
  if (OSMesaGetCurrentContext() == state_->context) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(state_->context);
}

void OffscreenContext::make_current() {
  if (!OSMesaMakeCurrent(state_->context, state_->pixels.data(), GL_UNSIGNED_BYTE, state_->width, state_->height))
    throw std::runtime_error("OSMesa could not make its context current");
}

int OffscreenContext::width() const { return state_->width; }
int OffscreenContext::height() const { return state_->height; }

std::string OffscreenContext::renderer() const {
  auto text = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VERSION) + ", " + text(GL_RENDERER);
}

}  // namespace amls
