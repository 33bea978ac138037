#include "render/gl_objects.hpp"

#include <stdexcept>

namespace amls {

template <GlObjectKind Kind>
GlObject<Kind>::GlObject() {
  if constexpr (Kind == GlObjectKind::buffer) glGenBuffers(1, &id_);
  if constexpr (Kind == GlObjectKind::vertex_array) glGenVertexArrays(1, &id_);
  if constexpr (Kind == GlObjectKind::program) id_ = glCreateProgram();
  if (id_ == 0) throw std::runtime_error("could not create an OpenGL object (is a context current?)");
}

template <GlObjectKind Kind>
void GlObject<Kind>::release() noexcept {
  if (id_ == 0) return;
  if constexpr (Kind == GlObjectKind::buffer) glDeleteBuffers(1, &id_);
  if constexpr (Kind == GlObjectKind::vertex_array) glDeleteVertexArrays(1, &id_);
  if constexpr (Kind == GlObjectKind::program) glDeleteProgram(id_);
  id_ = 0;
}

template class GlObject<GlObjectKind::buffer>;
template class GlObject<GlObjectKind::vertex_array>;
template class GlObject<GlObjectKind::program>;

}  // namespace amls
