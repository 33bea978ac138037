#pragma once
// 2D points as round dots of a constant pixel size, coloured like splats (shaders/point.vert, dot.frag).
#include "render/frame.hpp"
#include "render/point_buffers.hpp"
#include "render/shader_program.hpp"

namespace amls {

// Sets dot.frag's uniforms on a program in use: dots of `size_px` with a dark one-pixel outline.
void set_dot_uniforms(const ShaderProgram& program, float size_px);

class PointPass {
 public:
  PointPass();
  void draw(const PointBuffers& points, const Frame& frame) const;

 private:
  ShaderProgram program_;
};

}  // namespace amls
