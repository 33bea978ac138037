#include "render/point_buffers.hpp"

#include <stdexcept>
#include <string>

#include "render/gl_check.hpp"

namespace amls {

namespace {

// Attribute `location` reads `components` floats per point from `buffer`, advancing per
// vertex (divisor 0) or per instance (divisor 1). The vertex array must be bound.
void describe_attribute(GLuint location, const StreamBuffer& buffer, GLint components, GLuint divisor) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  glVertexAttribDivisor(location, divisor);
}

}  // namespace

PointBuffers::PointBuffers(BufferUpdate update) : positions_(update), normals_(update), scalars_(update) {
  describe_attributes();
  check_gl("creating the point buffers");
}

void PointBuffers::describe_attributes() {
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
}

void PointBuffers::upload(const PreparedPoints& points) {
  const bool positions_moved = positions_.write(std::as_bytes(std::span(points.positions)));
  const bool normals_moved = normals_.write(std::as_bytes(std::span(points.normals)));
  if (positions_moved || normals_moved) describe_attributes();
  count_ = points.size();
  set_scalars_enabled(false);
  check_gl("uploading points");
}

void PointBuffers::upload_scalars(std::span<const float> scalars) {
  if (scalars.size() != count_)
    throw std::invalid_argument("got " + std::to_string(scalars.size()) + " scalars for " + std::to_string(count_) +
                                " drawable points");
  if (scalars_.write(std::as_bytes(scalars))) describe_attributes();
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
