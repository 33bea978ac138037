#pragma once
// How the renderer writes its point buffers (render/stream_buffer.hpp): persistently
// mapped where the context can (GL_ARB_buffer_storage), or always with glBufferSubData
// (the fallback, forced so that tests cover it). No GL here.
namespace amls {

enum class BufferUpdate { best_available, sub_data };

}  // namespace amls
