#include "render/egl_context.hpp"

#include <cstdio>
#include <utility>

#include "render/gl_check.hpp"

namespace amls {

namespace {

const char* egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    case EGL_BAD_DEVICE_EXT: return "EGL_BAD_DEVICE_EXT";
    default: return "an unknown EGL error";
  }
}

std::runtime_error egl_failure(const std::string& what) { return std::runtime_error(what + " (" + egl_error_text() + ")"); }

// Initialises `display` (again, if it already is: EGL allows that) and returns its EGL
// version, major * 10 + minor. Displays are never terminated: eglGetPlatformDisplay gives every
// context on one device the same display, so terminating it would pull it from under the
// others, and it would unload Mesa's driver, whose allocations LeakSanitizer then reports as
// leaks of an unknown module that no suppression can name. One display per device lives until exit.
int initialise(EGLDisplay display) {
  EGLint major = 0;
  EGLint minor = 0;
  if (eglInitialize(display, &major, &minor) == EGL_FALSE) throw egl_failure("eglInitialize failed");
  return major * 10 + minor;
}

// The extensions EGL has without a display (EGL_EXT_client_extensions), or "" without any.
std::string egl_client_extensions() {
  // Without EGL_EXT_client_extensions this is an error (EGL_BAD_DISPLAY) and nullptr.
  const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  return extensions ? extensions : "";
}

GLADapiproc egl_gl_function(const char* name) { return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name)); }

class EglContext final : public HeadlessGl {
 public:
  EglContext(EGLDisplay display, HeadlessBackend backend, std::string device)
      : display_(display), backend_(backend), device_(std::move(device)) {
    const int version = initialise(display_);
    try {
      create(version);
    } catch (...) {
      destroy();
      throw;
    }
  }
  ~EglContext() override { destroy(); }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current() override {
    // The bound API is per thread: bind it on whichever thread makes the context current.
    if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) throw egl_failure("eglBindAPI(EGL_OPENGL_API) failed");
    if (eglMakeCurrent(display_, surface_, surface_, context_) == EGL_FALSE)
      throw egl_failure("eglMakeCurrent failed");
  }

  GLADloadfunc gl_loader() const override { return egl_gl_function; }

  void prepare_framebuffer(int width, int height) override {
    GLint largest = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
    if (width > largest || height > largest)
      throw std::runtime_error("the image, " + std::to_string(width) + "x" + std::to_string(height) +
                               ", exceeds this context's largest renderbuffer side, " + std::to_string(largest));
    glGenRenderbuffers(2, renderbuffers_);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers_[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers_[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, renderbuffers_[1]);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    check_gl("making the offscreen framebuffer");
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      char code[16];
      std::snprintf(code, sizeof code, "0x%04X", status);
      throw std::runtime_error(std::string("the offscreen framebuffer is incomplete (status ") + code + ")");
    }
    // The framebuffer stays bound: this context draws nowhere else.
    glViewport(0, 0, width, height);
  }

  HeadlessBackend backend() const override { return backend_; }
  std::string device() const override { return device_; }

 private:
  void create(int version) {
    const char* listed = eglQueryString(display_, EGL_EXTENSIONS);
    const std::string extensions = listed ? listed : "";
    if (version < 15 && !has_extension(extensions, "EGL_KHR_create_context"))
      throw std::runtime_error("the display offers EGL " + std::to_string(version / 10) + "." +
                               std::to_string(version % 10) +
                               " without EGL_KHR_create_context, so an OpenGL 3.3 core context cannot be asked for");
    if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE) throw egl_failure("the display offers no desktop OpenGL");

    const bool surfaceless = has_extension(extensions, "EGL_KHR_surfaceless_context");
    // The colour buffer is the framebuffer object's; the config only has to allow a context
    // (and, without EGL_KHR_surfaceless_context, a pbuffer to make it current with).
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                        EGL_SURFACE_TYPE,    surfaceless ? 0 : EGL_PBUFFER_BIT,
                                        EGL_RED_SIZE,        8,
                                        EGL_GREEN_SIZE,      8,
                                        EGL_BLUE_SIZE,       8,
                                        EGL_ALPHA_SIZE,      8,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (eglChooseConfig(display_, config_attributes, &config, 1, &configs) == EGL_FALSE)
      throw egl_failure("eglChooseConfig failed");
    if (configs == 0) throw std::runtime_error("the display has no RGBA8 config for desktop OpenGL");

    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context_ == EGL_NO_CONTEXT) throw egl_failure("eglCreateContext gave no OpenGL 3.3 core context");
    if (!surfaceless) {
      const EGLint pbuffer_attributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
      surface_ = eglCreatePbufferSurface(display_, config, pbuffer_attributes);
      if (surface_ == EGL_NO_SURFACE)
        throw egl_failure("the display has no EGL_KHR_surfaceless_context and eglCreatePbufferSurface failed");
    }
  }

  void destroy() noexcept {
    if (context_ != EGL_NO_CONTEXT && eglGetCurrentContext() == context_)
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    // The framebuffer and renderbuffers go with the context.
    if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  }

  EGLDisplay display_;
  HeadlessBackend backend_;
  std::string device_;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  GLuint framebuffer_ = 0;
  GLuint renderbuffers_[2] = {0, 0};
};

}  // namespace

std::string egl_error_text() {
  const EGLint code = eglGetError();
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(code));
  return std::string(egl_error_name(code)) + " (" + hex + ")";
}

void require_egl_client_extensions(std::initializer_list<const char*> names) {
  const std::string client = egl_client_extensions();
  if (client.empty())
    throw std::runtime_error("libEGL lists no client extensions: it found no EGL driver (Mesa's is libegl-mesa0; "
                             "glvnd reads the drivers from /usr/share/glvnd/egl_vendor.d)");
  // EGL_EXT_device_base is the older name of device_enumeration and device_query together,
  // and the one NVIDIA's driver lists.
  const bool device_base = has_extension(client, "EGL_EXT_device_base");
  for (const std::string name : names) {
    const bool in_base = name == "EGL_EXT_device_enumeration" || name == "EGL_EXT_device_query";
    if (!has_extension(client, name.c_str()) && !(in_base && device_base))
      throw std::runtime_error("libEGL lacks " + name + " (it lists: " + client + ")");
  }
}

EGLDisplay egl_platform_display(EGLenum platform, void* native_display, const char* platform_extension) {
  require_egl_client_extensions({"EGL_EXT_platform_base", platform_extension});
  const auto get_display = egl_function<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  const EGLDisplay display = get_display(platform, native_display, nullptr);
  if (display == EGL_NO_DISPLAY) throw egl_failure("eglGetPlatformDisplayEXT gave no display");
  return display;
}

std::unique_ptr<HeadlessGl> make_egl_context(EGLDisplay display, HeadlessBackend backend, std::string device) {
  return std::make_unique<EglContext>(display, backend, std::move(device));
}

}  // namespace amls
