#pragma once
// The 2D background grid, computed per pixel (shaders/grid.*); planar camera only.
#include "render/frame.hpp"
#include "render/gl_objects.hpp"
#include "render/shader_program.hpp"

namespace amls {

class GridPass {
 public:
  GridPass();
  // Lines every `spacing` world units; draws nothing for a perspective view or spacing <= 0.
  void draw(const Frame& frame, float spacing) const;

 private:
  ShaderProgram program_;
  GlVertexArray empty_array_;  // core profile draws need a vertex array even without attributes
};

}  // namespace amls
