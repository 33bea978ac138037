#include "render/point_pass.hpp"

namespace amls {

void set_dot_uniforms(const ShaderProgram& program, float size_px) {
  program.set("u_point_size", size_px);
  program.set("u_outline_px", size_px >= 6.0f ? 1.0f : 0.0f);
  program.set("u_outline_color", glm::vec4(0.05f, 0.05f, 0.05f, 1.0f));
}

PointPass::PointPass()
    : program_("2D points", {{GL_VERTEX_SHADER, {"color.glsl", "point.vert"}}, {GL_FRAGMENT_SHADER, {"dot.frag"}}}) {}

void PointPass::draw(const PointBuffers& points, const Frame& frame) const {
  if (points.count() == 0) return;
  program_.use();
  set_color_uniforms(program_, frame);
  set_dot_uniforms(program_, frame.options.point_size_px);
  program_.set("u_view_projection", frame.view_projection);
  points.bind_per_vertex();
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(points.count()));
}

}  // namespace amls
