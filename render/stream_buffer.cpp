#include "render/stream_buffer.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

namespace amls {

namespace {

constexpr GLbitfield kPersistentWrite = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

// Waits until the GPU has run every command sent so far: a draw still reading
// a persistently mapped store must not see it change under it. Called once per
// replacement, a frame or more after the last draw, so it rarely waits.
void wait_for_gpu() {
  GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  GLenum status = GL_TIMEOUT_EXPIRED;
  while (status == GL_TIMEOUT_EXPIRED) status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 100'000'000);
  glDeleteSync(fence);
}

}  // namespace

StreamBuffer::StreamBuffer(BufferUpdate update)
    : persistent_(update == BufferUpdate::best_available && GLAD_GL_ARB_buffer_storage != 0) {}

bool StreamBuffer::write(std::span<const std::byte> bytes) {
  if (bytes.empty()) return false;
  // Past the store, or using less than half of it (give the memory back): a new store.
  if (bytes.size() > capacity_ || 2 * bytes.size() < capacity_)
    return reallocate(bytes, bytes.size() + bytes.size() / 8);
  if (persistent_) {
    wait_for_gpu();
    std::memcpy(mapped_, bytes.data(), bytes.size());
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
  }
  return false;
}

bool StreamBuffer::reallocate(std::span<const std::byte> bytes, std::size_t capacity) {
  const auto size = static_cast<GLsizeiptr>(capacity);
  capacity_ = 0;  // until the new store holds `bytes`
  if (persistent_) {
    // An immutable store cannot be resized: a new buffer object (deleting the old one unmaps it).
    buffer_ = GlBuffer();
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glBufferStorage(GL_ARRAY_BUFFER, size, nullptr, kPersistentWrite);
    mapped_ = static_cast<std::byte*>(glMapBufferRange(GL_ARRAY_BUFFER, 0, size, kPersistentWrite));
    if (mapped_ == nullptr) {
      glBindBuffer(GL_ARRAY_BUFFER, 0);
      throw std::runtime_error("could not map a point buffer of " + std::to_string(capacity) + " bytes");
    }
    std::memcpy(mapped_, bytes.data(), bytes.size());
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    glBufferData(GL_ARRAY_BUFFER, size, nullptr, GL_DYNAMIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  capacity_ = capacity;
  return persistent_;
}

}  // namespace amls
