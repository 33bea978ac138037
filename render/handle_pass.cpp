#include "render/handle_pass.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/gl_check.hpp"
#include "render/point_pass.hpp"

namespace amls {

namespace {

struct HandleVertex {
  glm::vec3 position;
  float state;
};

}  // namespace

HandlePass::HandlePass()
    : program_("handles", {{GL_VERTEX_SHADER, {"handle.vert"}}, {GL_FRAGMENT_SHADER, {"dot.frag"}}}) {
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(HandleVertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, sizeof(HandleVertex),
                        reinterpret_cast<const void*>(offsetof(HandleVertex, state)));
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void HandlePass::set_handles(std::span<const Handle> handles) {
  std::vector<HandleVertex> vertices;
  vertices.reserve(handles.size());
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const glm::vec3& p = handles[i].position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw std::invalid_argument("handle " + std::to_string(i) + " has a non-finite position");
    vertices.push_back({p, static_cast<float>(handles[i].state)});
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(HandleVertex)), vertices.data(),
               GL_DYNAMIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  count_ = vertices.size();
  check_gl("uploading handles");
}

void HandlePass::draw(const Frame& frame) const {
  if (count_ == 0) return;
  program_.use();
  set_dot_uniforms(program_, frame.options.handle_size_px);
  program_.set("u_view_projection", frame.view_projection);
  glm::vec4 colors[4];
  for (int i = 0; i < 4; ++i) colors[i] = glm::vec4(frame.options.handle_colors[static_cast<std::size_t>(i)], 1.0f);
  program_.set("u_state_colors", colors, 4);
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count_));
}

}  // namespace amls
