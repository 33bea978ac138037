#pragma once
// The GLSL files of shaders/, embedded in the binary at build time
// (cmake/embed_shaders.cmake), so that programs run from any directory.
#include <span>
#include <string_view>

namespace amls {

struct EmbeddedFile {
  std::string_view name;  // file name in shaders/, e.g. "splat.vert"
  std::string_view text;
};

// Every embedded file (defined in the generated embedded_shaders.cpp).
std::span<const EmbeddedFile> embedded_shader_files();

// The text of shaders/<name>; throws std::out_of_range naming the file if it was not embedded.
std::string_view shader_source(std::string_view name);

}  // namespace amls
