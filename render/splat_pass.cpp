#include "render/splat_pass.hpp"

namespace amls {

SplatPass::SplatPass()
    : program_("splats", {{GL_VERTEX_SHADER, {"color.glsl", "lighting.glsl", "splat.vert"}},
                          {GL_FRAGMENT_SHADER, {"splat.frag"}}}) {
  GLfloat range[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, range);
  max_point_size_ = range[1];
}

void SplatPass::draw(const PointBuffers& points, const Frame& frame) const {
  if (points.count() == 0) return;
  program_.use();
  set_color_uniforms(program_, frame);
  program_.set("u_view", frame.view);
  program_.set("u_projection", frame.projection);
  program_.set("u_viewport", frame.viewport_vector());
  // gl_FragCoord -> NDC -> view-space ray (divide by the focal lengths P[0][0], P[1][1]).
  const glm::vec4 v = frame.viewport_vector();
  const glm::vec2 focal{frame.projection[0][0], frame.projection[1][1]};
  const glm::vec2 scale = 2.0f / (glm::vec2(v.z, v.w) * focal);
  const glm::vec2 offset = -(2.0f * glm::vec2(v.x, v.y) / glm::vec2(v.z, v.w) + 1.0f) / focal;
  program_.set("u_pixel_to_ray", glm::vec4(scale, offset));
  program_.set("u_radius", frame.options.splat_scale * frame.spacing);
  program_.set("u_near", frame.near_plane);
  program_.set("u_perspective", frame.perspective() ? 1 : 0);
  program_.set("u_max_point_size", max_point_size_);
  program_.set("u_back_color", frame.options.back_color);
  program_.set("u_cull_back_faces", frame.options.cull_back_faces ? 1 : 0);
  points.bind_per_vertex();
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(points.count()));
}

}  // namespace amls
