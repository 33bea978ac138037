#pragma once
// A linked GLSL 330 core program built from embedded shader files, with uniform setters.
#include <glm/glm.hpp>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl_objects.hpp"

namespace amls {

// One stage: its main file and the library files (e.g. "color.glsl") put before it.
struct ShaderStage {
  GLenum type;                          // GL_VERTEX_SHADER or GL_FRAGMENT_SHADER
  std::vector<std::string_view> files;  // library files first, the stage's own file last
};

class ShaderProgram {
 public:
  // Compiles and links; throws std::runtime_error with the compiler's log, each
  // message naming the file it is about (Mesa prints "<string index>:<line>").
  ShaderProgram(std::string label, std::initializer_list<ShaderStage> stages);

  void use() const;
  GLuint id() const { return program_.id(); }

  // Uniforms that the linker removed (unused) are silently ignored, as in GL.
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const glm::vec4* values, int count) const;

 private:
  GLint location(const char* name) const;

  std::string label_;
  GlProgram program_;
};

}  // namespace amls
