#include "render/shader_program.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>

#include "render/shader_sources.hpp"

namespace amls {

namespace {

constexpr std::string_view kVersion = "#version 330 core\n";

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  if (is_program)
    glGetProgramInfoLog(object, length, nullptr, log.data());
  else
    glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.c_str();
}

// Compiles one stage from several source strings; string 0 is the #version line,
// string i (i >= 1) is files[i - 1], which is how the log's "i:line" maps back to files.
GLuint compile(const std::string& label, const ShaderStage& stage) {
  std::vector<const GLchar*> texts{kVersion.data()};
  std::vector<GLint> lengths{static_cast<GLint>(kVersion.size())};
  std::string names;
  for (std::size_t i = 0; i < stage.files.size(); ++i) {
    const std::string_view text = shader_source(stage.files[i]);
    texts.push_back(text.data());
    lengths.push_back(static_cast<GLint>(text.size()));
    // (appended piecewise: GCC 12 warns falsely, -Wrestrict, on " " + std::string at -O3)
    names.append(1, ' ').append(std::to_string(i + 1)).append(1, '=').append(stage.files[i]);
  }
  const GLuint shader = glCreateShader(stage.type);
  glShaderSource(shader, static_cast<GLsizei>(texts.size()), texts.data(), lengths.data());
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = info_log(shader, false);
    glDeleteShader(shader);
    throw std::runtime_error("compiling shader program '" + label + "' (source strings:" + names + ") failed:\n" + log);
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(std::string label, std::initializer_list<ShaderStage> stages) : label_(std::move(label)) {
  std::vector<GLuint> shaders;
  try {
    for (const ShaderStage& stage : stages) shaders.push_back(compile(label_, stage));
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  for (GLuint s : shaders) glAttachShader(program_.id(), s);
  glLinkProgram(program_.id());
  for (GLuint s : shaders) {
    glDetachShader(program_.id(), s);
    glDeleteShader(s);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE)
    throw std::runtime_error("linking shader program '" + label_ + "' failed:\n" + info_log(program_.id(), true));
}

void ShaderProgram::use() const { glUseProgram(program_.id()); }

GLint ShaderProgram::location(const char* name) const { return glGetUniformLocation(program_.id(), name); }

void ShaderProgram::set(const char* name, int value) const { glUniform1i(location(name), value); }
void ShaderProgram::set(const char* name, float value) const { glUniform1f(location(name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(location(name), 1, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(const char* name, const glm::vec4* values, int count) const {
  glUniform4fv(location(name), count, glm::value_ptr(*values));
}

}  // namespace amls
