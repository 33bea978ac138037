#include "render/gl_check.hpp"

#include <stdexcept>
#include <string>

#include "render/gl.hpp"

namespace amls {

namespace {

const char* gl_error_name(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "unknown GL error";
  }
}

}  // namespace

void check_gl(const char* what) {
  const GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  // Drain the queue so that the next check reports only what comes after this one.
  while (glGetError() != GL_NO_ERROR) {
  }
  throw std::runtime_error(std::string("OpenGL error ") + gl_error_name(first) + " after " + what);
}

void require_gl_context(const char* who) {
  if (glad_glGetString == nullptr || glad_glGetString(GL_VERSION) == nullptr)
    throw std::runtime_error(std::string(who) +
                             " needs a current OpenGL 3.3 core context with the GL loader initialised "
                             "(gladLoadGL), and none is");
  if (!GLAD_GL_VERSION_3_3)
    throw std::runtime_error(std::string(who) + " needs OpenGL 3.3 core; the current context is older");
}

}  // namespace amls
