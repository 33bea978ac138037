// The osmesa kind of headless context: Mesa's OSMesa (llvmpipe) rendering into a colour
// buffer in memory. Built only where OSMesa is found (AMLS_WITH_OSMESA); Mesa removed
// OSMesa in 25.1, so EGL comes first.
#include <stdexcept>
#include <vector>

// glad first: it must precede GL/gl.h, which osmesa.h includes (kept in order by hand).
// clang-format off
#include "render/headless_gl.hpp"
#include <GL/osmesa.h>
// clang-format on

namespace amls {

namespace {

GLADapiproc osmesa_gl_function(const char* name) {
  return reinterpret_cast<GLADapiproc>(OSMesaGetProcAddress(name));
}

class OsmesaContext final : public HeadlessGl {
 public:
  OsmesaContext(int width, int height)
      : width_(width), height_(height), pixels_(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    const int attributes[] = {OSMESA_FORMAT,        OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,    24,
                              OSMESA_STENCIL_BITS,  8,
                              OSMESA_ACCUM_BITS,    0,
                              OSMESA_PROFILE,       OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesaCreateContextAttribs gave no OpenGL 3.3 core context");
  }
  ~OsmesaContext() override {
    if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(context_);
  }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  void make_current() override {
    if (!OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, width_, height_))
      throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                               std::to_string(height_) + " buffer");
  }
  GLADloadfunc gl_loader() const override { return osmesa_gl_function; }
  HeadlessBackend backend() const override { return HeadlessBackend::osmesa; }

 private:
  OSMesaContext context_ = nullptr;
  int width_;
  int height_;
  std::vector<unsigned char> pixels_;  // the colour buffer OSMesa renders into, bottom-up
};

}  // namespace

std::unique_ptr<HeadlessGl> open_osmesa(int width, int height) {
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace amls
