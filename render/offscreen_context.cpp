#include "render/offscreen_context.hpp"

#include <atomic>
#include <cstdint>
#include <stdexcept>

#include "core/util/parameter_ranges.hpp"
#include "render/headless_gl.hpp"

namespace amls {

namespace {

// Which context glad's table was last loaded for (0: none), so that make_current reloads it
// only after another context's turn. Each context gets a number that is never reused.
std::atomic<std::uint64_t> next_context_number{1};
std::uint64_t gl_functions_loaded_for = 0;

std::unique_ptr<HeadlessGl> open_backend(HeadlessBackend backend, const HeadlessGlChoice& choice, int width,
                                         int height) {
  switch (backend) {
#if AMLS_HAVE_EGL
    case HeadlessBackend::egl_device:
      return open_egl_device(choice.egl_device);
    case HeadlessBackend::egl_surfaceless:
      return open_egl_surfaceless();
#endif
#if AMLS_HAVE_OSMESA
    case HeadlessBackend::osmesa:
      return open_osmesa(width, height);
#endif
    default:
      break;
  }
  (void)choice;
  (void)width;
  (void)height;
  throw std::runtime_error(std::string("this build does not have ") + to_string(backend));
}

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? std::string(reinterpret_cast<const char*>(text)) : std::string("?");
}

}  // namespace

std::vector<HeadlessBackend> headless_backends_built() {
  std::vector<HeadlessBackend> built;
#if AMLS_HAVE_EGL
  built.push_back(HeadlessBackend::egl_device);
  built.push_back(HeadlessBackend::egl_surfaceless);
#endif
#if AMLS_HAVE_OSMESA
  built.push_back(HeadlessBackend::osmesa);
#endif
  return built;
}

std::vector<std::string> egl_device_extensions() {
#if AMLS_HAVE_EGL
  try {
    return list_egl_device_extensions();
  } catch (const std::runtime_error&) {
    return {};
  }
#else
  return {};
#endif
}

struct OffscreenContext::State {
  std::unique_ptr<HeadlessGl> gl;
  std::uint64_t number = next_context_number++;
  int width = 0;
  int height = 0;
  HeadlessGlInfo info;
};

OffscreenContext::OffscreenContext(int width, int height)
    : OffscreenContext(width, height, headless_gl_choice_from_environment()) {}

OffscreenContext::OffscreenContext(int width, int height, const HeadlessGlChoice& choice)
    : state_(std::make_unique<State>()) {
  check_range("offscreen image width", width, ranges::kImageSide);
  check_range("offscreen image height", height, ranges::kImageSide);
  state_->width = width;
  state_->height = height;
  std::vector<std::string> failures;
  for (HeadlessBackend backend : headless_backend_order(choice, headless_backends_built())) {
    try {
      state_->gl = open_backend(backend, choice, width, height);
      make_current();
      if (!GLAD_GL_VERSION_3_3)
        throw std::runtime_error("the context offers OpenGL " + gl_string(GL_VERSION) + ", not 3.3 core");
      state_->gl->prepare_framebuffer(width, height);
      state_->info = {backend, state_->gl->device(), gl_string(GL_VERSION), gl_string(GL_RENDERER), failures};
      return;
    } catch (const std::runtime_error& e) {
      state_->gl.reset();
      if (gl_functions_loaded_for == state_->number) gl_functions_loaded_for = 0;  // the next backend loads its own
      failures.push_back(std::string(to_string(backend)) + ": " + e.what());
    }
  }
  std::string tried;
  for (const std::string& failure : failures) tried += "\n  " + failure;
  throw std::runtime_error("no headless OpenGL 3.3 core context could be made (" + std::string(kGlBackendVariable) +
                           " and " + kEglDeviceVariable + " choose the backend and device); tried:" + tried);
}

OffscreenContext::~OffscreenContext() {
  // glad's table stays loaded: a GL call without a current context is then a harmless no-op.
  if (gl_functions_loaded_for == state_->number) gl_functions_loaded_for = 0;
}

void OffscreenContext::make_current() {
  state_->gl->make_current();
  if (gl_functions_loaded_for == state_->number) return;
  if (gladLoadGL(state_->gl->gl_loader()) == 0)
    throw std::runtime_error(std::string("could not load the OpenGL functions through ") +
                             to_string(state_->gl->backend()));
  gl_functions_loaded_for = state_->number;
}

int OffscreenContext::width() const { return state_->width; }
int OffscreenContext::height() const { return state_->height; }
const HeadlessGlInfo& OffscreenContext::info() const { return state_->info; }

}  // namespace amls
