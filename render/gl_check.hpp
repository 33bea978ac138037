#pragma once
// Turns pending OpenGL errors into an exception that names what was being done.
namespace amls {

// Throws std::runtime_error("OpenGL error GL_... after <what>") if glGetError reports one.
void check_gl(const char* what);

// Throws std::runtime_error unless a GL 3.3 (or later) context is current and loaded.
void require_gl_context(const char* who);

}  // namespace amls
