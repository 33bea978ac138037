#include "render/shader_sources.hpp"

#include <stdexcept>
#include <string>

namespace amls {

std::string_view shader_source(std::string_view name) {
  for (const EmbeddedFile& file : embedded_shader_files())
    if (file.name == name) return file.text;
  throw std::out_of_range("no shader named '" + std::string(name) + "' is embedded (list it in render/CMakeLists.txt)");
}

}  // namespace amls
