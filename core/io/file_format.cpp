#include "core/io/file_format.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <utility>

namespace amls {

std::string lower_case(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::string lower_extension(const std::string& path) {
  return lower_case(std::filesystem::path(path).extension().string());
}

std::optional<ShapeFileFormat> shape_file_format(const std::string& path) {
  static constexpr std::array<std::pair<std::string_view, ShapeFileFormat>, 8> kExtensions{{
      {".ply", ShapeFileFormat::ply},
      {".off", ShapeFileFormat::off},
      {".obj", ShapeFileFormat::obj},
      {".stl", ShapeFileFormat::stl},
      {".xyz", ShapeFileFormat::xyz},
      {".pwn", ShapeFileFormat::xyz},  // CGAL's points with normals: x y z nx ny nz
      {".csv", ShapeFileFormat::xyz},
      {".txt", ShapeFileFormat::xyz},
  }};
  const std::string extension = lower_extension(path);
  for (const auto& [name, format] : kExtensions)
    if (name == extension) return format;
  return std::nullopt;
}

bool is_point_set_file(const std::string& path) {
  const std::optional<ShapeFileFormat> format = shape_file_format(path);
  return format && *format != ShapeFileFormat::obj && *format != ShapeFileFormat::stl;
}

}  // namespace amls
