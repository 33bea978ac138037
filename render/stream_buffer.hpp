#pragma once
// A GL array buffer whose contents are replaced whole, often and large: the
// editor's points, a million of them every step of a drag. A replacement that
// fits the store is written into it instead of into a new one, and a new store
// keeps an eighth more room, so that a point count that changes a little from
// step to step (local resampling) still fits. Where the context has
// GL_ARB_buffer_storage (core in GL 4.4; asked for at run time, the editor
// needs only 3.3) the store is mapped once, persistently and coherently, and a
// replacement is one copy into it; elsewhere it is glBufferSubData. Every call
// needs the context the buffer was made in current.
#include <cstddef>
#include <span>

#include "render/buffer_update.hpp"
#include "render/gl_objects.hpp"

namespace amls {

class StreamBuffer {
 public:
  explicit StreamBuffer(BufferUpdate update);

  // Replaces the contents with `bytes` (nothing happens for none). Returns true
  // if the buffer object changed: vertex arrays that read it must be pointed
  // at id() again.
  bool write(std::span<const std::byte> bytes);

  GLuint id() const { return buffer_.id(); }
  bool persistent() const { return persistent_; }

 private:
  // A store of `capacity` bytes holding `bytes` at its start.
  bool reallocate(std::span<const std::byte> bytes, std::size_t capacity);

  GlBuffer buffer_;
  bool persistent_ = false;
  std::size_t capacity_ = 0;    // bytes of the store; 0: none yet
  std::byte* mapped_ = nullptr;  // the persistent mapping of the whole store
};

}  // namespace amls
