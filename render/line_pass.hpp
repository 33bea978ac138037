#pragma once
// Lines: the MLS curve (segments given in world coordinates) and the points' normals
// (drawn instanced from the point buffers, no CPU work per frame).
#include <span>

#include "render/frame.hpp"
#include "render/gl_objects.hpp"
#include "render/point_buffers.hpp"
#include "render/shader_program.hpp"

namespace amls {

class LinePass {
 public:
  LinePass();
  // Segment endpoints in pairs (a0, b0, a1, b1, ...). Throws std::invalid_argument for an odd
  // count or a non-finite endpoint.
  void set_segments(std::span<const glm::vec3> endpoints);
  std::size_t segment_count() const { return endpoint_count_ / 2; }

  void draw_segments(const Frame& frame) const;
  void draw_normals(const PointBuffers& points, const Frame& frame) const;

 private:
  void set_line_width(const Frame& frame) const;

  ShaderProgram segment_program_;
  ShaderProgram normal_program_;
  GlBuffer segments_;
  GlVertexArray segment_array_;
  std::size_t endpoint_count_ = 0;
  float max_line_width_ = 1.0f;
};

}  // namespace amls
