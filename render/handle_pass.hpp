#pragma once
// Deformation handles: round dots of a constant pixel size drawn over everything
// (depth test off), coloured by state (shaders/handle.vert, dot.frag).
#include <span>

#include "render/frame.hpp"
#include "render/gl_objects.hpp"
#include "render/shader_program.hpp"

namespace amls {

class HandlePass {
 public:
  HandlePass();
  // Throws std::invalid_argument naming the first handle with a non-finite position.
  void set_handles(std::span<const Handle> handles);
  std::size_t count() const { return count_; }
  void draw(const Frame& frame) const;

 private:
  ShaderProgram program_;
  GlBuffer buffer_;
  GlVertexArray vertex_array_;
  std::size_t count_ = 0;
};

}  // namespace amls
