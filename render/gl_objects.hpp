#pragma once
// Owning handles for OpenGL objects: moved, never copied; deleted with their owner.
// They must be destroyed while the context that made them is current.
#include <utility>

#include "render/gl.hpp"

namespace amls {

enum class GlObjectKind { buffer, vertex_array, program };

template <GlObjectKind Kind>
class GlObject {
 public:
  GlObject();  // creates the object (a context must be current)
  ~GlObject() { release(); }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      release();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  GLuint id() const { return id_; }

 private:
  void release() noexcept;
  GLuint id_ = 0;
};

using GlBuffer = GlObject<GlObjectKind::buffer>;
using GlVertexArray = GlObject<GlObjectKind::vertex_array>;
using GlProgram = GlObject<GlObjectKind::program>;

extern template class GlObject<GlObjectKind::buffer>;
extern template class GlObject<GlObjectKind::vertex_array>;
extern template class GlObject<GlObjectKind::program>;

}  // namespace amls
