#include "render/line_pass.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/gl_check.hpp"

namespace amls {

LinePass::LinePass()
    : segment_program_("curve", {{GL_VERTEX_SHADER, {"line.vert"}}, {GL_FRAGMENT_SHADER, {"line.frag"}}}),
      normal_program_("normals", {{GL_VERTEX_SHADER, {"normals.vert"}}, {GL_FRAGMENT_SHADER, {"line.frag"}}}) {
  glBindVertexArray(segment_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, segments_.id());
  glEnableVertexAttribArray(kPositionAttribute);
  glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  // Core profile allows wide lines up to the implementation's limit, and none at all in a
  // forward-compatible context (where glLineWidth > 1 is an error).
  GLint flags = 0;
  glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
  max_line_width_ = (flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT) != 0 ? 1.0f : std::max(range[1], 1.0f);
  check_gl("creating the line pass");
}

void LinePass::set_segments(std::span<const glm::vec3> endpoints) {
  if (endpoints.size() % 2 != 0)
    throw std::invalid_argument("curve segments come in endpoint pairs; got " + std::to_string(endpoints.size()) +
                                " endpoints");
  for (std::size_t i = 0; i < endpoints.size(); ++i) {
    const glm::vec3& p = endpoints[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument("curve endpoint " + std::to_string(i) + " is not finite");
  }
  glBindBuffer(GL_ARRAY_BUFFER, segments_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(endpoints.size_bytes()), endpoints.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  endpoint_count_ = endpoints.size();
  check_gl("uploading curve segments");
}

void LinePass::set_line_width(const Frame& frame) const {
  glLineWidth(std::clamp(frame.options.line_width_px, 1.0f, max_line_width_));
}

void LinePass::draw_segments(const Frame& frame) const {
  if (endpoint_count_ == 0) return;
  segment_program_.use();
  segment_program_.set("u_view_projection", frame.view_projection);
  segment_program_.set("u_color", glm::vec4(frame.options.curve_color, 1.0f));
  set_line_width(frame);
  glBindVertexArray(segment_array_.id());
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(endpoint_count_));
}

void LinePass::draw_normals(const PointBuffers& points, const Frame& frame) const {
  if (points.count() == 0) return;
  normal_program_.use();
  normal_program_.set("u_view_projection", frame.view_projection);
  normal_program_.set("u_length", frame.options.normal_length * frame.spacing);
  normal_program_.set("u_color", glm::vec4(frame.options.normal_color, 1.0f));
  set_line_width(frame);
  points.bind_per_instance();
  glDrawArraysInstanced(GL_LINES, 0, 2, static_cast<GLsizei>(points.count()));
}

}  // namespace amls
