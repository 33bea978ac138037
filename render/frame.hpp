#pragma once
// What every pass needs for one SplatRenderer::draw, computed once per frame.
#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/render_options.hpp"

namespace amls {

class ShaderProgram;

struct Frame {
  const RenderOptions& options;
  Viewport viewport;
  Camera::Mode mode = Camera::Mode::orbit;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 view_projection{1.0f};
  float near_plane = 0.0f;  // perspective only
  float spacing = 1.0f;     // point spacing (h), world units
  // The colour mode and scalar range actually used (scalar falls back to uniform without scalars).
  ColorMode color_mode = ColorMode::uniform;
  glm::vec2 scalar_range{0.0f, 1.0f};

  bool perspective() const { return mode == Camera::Mode::orbit; }
  glm::vec4 viewport_vector() const {
    return {static_cast<float>(viewport.x), static_cast<float>(viewport.y), static_cast<float>(viewport.width),
            static_cast<float>(viewport.height)};
  }
};

// Sets color.glsl's uniforms on a program in use.
void set_color_uniforms(const ShaderProgram& program, const Frame& frame);

}  // namespace amls
