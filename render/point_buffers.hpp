#pragma once
// A point set on the GPU: buffers of positions, normals and scalars, uploaded once; two vertex arrays over them: one
// point per vertex (splats, dots) and one point per instance (normal segments, two vertices each).
#include <cstddef>
#include <span>

#include "render/gl_objects.hpp"
#include "render/point_data.hpp"

namespace amls {

// Vertex attribute locations shared by every point shader (layout(location = ...)).
inline constexpr GLuint kPositionAttribute = 0;
inline constexpr GLuint kNormalAttribute = 1;
inline constexpr GLuint kScalarAttribute = 2;

class PointBuffers {
 public:
  PointBuffers();

  // Replaces the points; drops the scalars.
  void upload(const PreparedPoints& points);
  // One scalar per uploaded (drawable) point.
  void upload_scalars(std::span<const float> scalars);
  void drop_scalars() { set_scalars_enabled(false); }
  void clear();

  std::size_t count() const { return count_; }
  bool has_scalars() const { return has_scalars_; }

  void bind_per_vertex() const { glBindVertexArray(per_vertex_.id()); }
  void bind_per_instance() const { glBindVertexArray(per_instance_.id()); }

 private:
  void set_scalars_enabled(bool enabled);

  GlBuffer positions_;
  GlBuffer normals_;
  GlBuffer scalars_;
  GlVertexArray per_vertex_;
  GlVertexArray per_instance_;
  std::size_t count_ = 0;
  bool has_scalars_ = false;
};

}  // namespace amls
