#include "render/grid_pass.hpp"

#include <cmath>

namespace amls {

GridPass::GridPass() : program_("grid", {{GL_VERTEX_SHADER, {"grid.vert"}}, {GL_FRAGMENT_SHADER, {"grid.frag"}}}) {}

void GridPass::draw(const Frame& frame, float spacing) const {
  if (frame.perspective() || !(spacing > 0.0f) || !std::isfinite(spacing)) return;
  program_.use();
  program_.set("u_inverse_view_projection", glm::inverse(frame.view_projection));
  program_.set("u_origin", frame.options.grid_origin);
  program_.set("u_spacing", spacing);
  program_.set("u_color", glm::vec4(frame.options.grid_color, 1.0f));
  glBindVertexArray(empty_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace amls
