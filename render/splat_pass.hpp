#pragma once
// 3D points as oriented, lit disks: one draw call of GL_POINTS over the point
// buffers, the disk cut out per pixel by a ray-disk test (shaders/splat.*).
// A splat's square is capped at GL_POINT_SIZE_RANGE's maximum (255 px on llvmpipe), so
// a view zoomed in until single splats span more than that shows them cut square.
#include "render/frame.hpp"
#include "render/point_buffers.hpp"
#include "render/shader_program.hpp"

namespace amls {

class SplatPass {
 public:
  SplatPass();
  // Draws with the depth test on; the caller has enabled GL_PROGRAM_POINT_SIZE.
  void draw(const PointBuffers& points, const Frame& frame) const;

 private:
  ShaderProgram program_;
  float max_point_size_ = 1.0f;
};

}  // namespace amls
