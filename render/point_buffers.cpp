#include "render/point_buffers.hpp"

#include <stdexcept>
#include <string>

#include "render/gl_check.hpp"

namespace amls {

namespace {

// Attribute `location` reads `components` floats per point from `buffer`, advancing per
// vertex (divisor 0) or per instance (divisor 1). The vertex array must be bound.
void describe_attribute(GLuint location, const GlBuffer& buffer, GLint components, GLuint divisor) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  glVertexAttribDivisor(location, divisor);
}

template <typename T>
void fill(const GlBuffer& buffer, std::span<const T> data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size_bytes()), data.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

}  // namespace

PointBuffers::PointBuffers() {
  for (GLuint divisor : {0u, 1u}) {
    glBindVertexArray((divisor == 0 ? per_vertex_ : per_instance_).id());
    describe_attribute(kPositionAttribute, positions_, 3, divisor);
    describe_attribute(kNormalAttribute, normals_, 3, divisor);
    describe_attribute(kScalarAttribute, scalars_, 1, divisor);
    glEnableVertexAttribArray(kPositionAttribute);
    glEnableVertexAttribArray(kNormalAttribute);
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  check_gl("creating the point buffers");
}

void PointBuffers::upload(const PreparedPoints& points) {
  fill<glm::vec3>(positions_, points.positions);
  fill<glm::vec3>(normals_, points.normals);
  count_ = points.size();
  set_scalars_enabled(false);
  check_gl("uploading points");
}

void PointBuffers::upload_scalars(std::span<const float> scalars) {
  if (scalars.size() != count_)
    throw std::invalid_argument("got " + std::to_string(scalars.size()) + " scalars for " + std::to_string(count_) +
                                " drawable points");
  fill<float>(scalars_, scalars);
  set_scalars_enabled(true);
  check_gl("uploading point scalars");
}

void PointBuffers::clear() {
  count_ = 0;
  set_scalars_enabled(false);
}

void PointBuffers::set_scalars_enabled(bool enabled) {
  for (const GlVertexArray* vao : {&per_vertex_, &per_instance_}) {
    glBindVertexArray(vao->id());
    if (enabled)
      glEnableVertexAttribArray(kScalarAttribute);
    else
      glDisableVertexAttribArray(kScalarAttribute);
  }
  glBindVertexArray(0);
  has_scalars_ = enabled;
}

}  // namespace amls
