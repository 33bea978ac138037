#pragma once
// A point set on the GPU: buffers of positions, normals and scalars, replaced whole when the points change (into
// the same stores where they fit: stream_buffer.hpp); two vertex arrays over them: one point per vertex (splats,
// dots) and one point per instance (normal segments, two vertices each).
#include <cstddef>
#include <span>

#include "render/gl_objects.hpp"
#include "render/point_data.hpp"
#include "render/stream_buffer.hpp"

namespace amls {

// Vertex attribute locations shared by every point shader (layout(location = ...)).
inline constexpr GLuint kPositionAttribute = 0;
inline constexpr GLuint kNormalAttribute = 1;
inline constexpr GLuint kScalarAttribute = 2;

class PointBuffers {
 public:
  explicit PointBuffers(BufferUpdate update);

  // Replaces the points; drops the scalars.
  void upload(const PreparedPoints& points);
  // One scalar per uploaded (drawable) point.
  void upload_scalars(std::span<const float> scalars);
  void drop_scalars() { set_scalars_enabled(false); }
  void clear();

  std::size_t count() const { return count_; }
  bool has_scalars() const { return has_scalars_; }
  bool persistent() const { return positions_.persistent(); }

  void bind_per_vertex() const { glBindVertexArray(per_vertex_.id()); }
  void bind_per_instance() const { glBindVertexArray(per_instance_.id()); }

 private:
  // Points both vertex arrays at the buffers (again, after a buffer object changed).
  void describe_attributes();
  void set_scalars_enabled(bool enabled);

  StreamBuffer positions_;
  StreamBuffer normals_;
  StreamBuffer scalars_;
  GlVertexArray per_vertex_;
  GlVertexArray per_instance_;
  std::size_t count_ = 0;
  bool has_scalars_ = false;
};

}  // namespace amls
