#pragma once
// Which reader a shape file goes to, by its extension (in any case):
//   .ply                      PLY, a point set or a mesh (core/io/ply_format.cpp)
//   .off                      OFF, a point set or a mesh (core/io/off_format.cpp)
//   .obj                      Wavefront OBJ, a mesh (core/io/mesh_io.cpp)
//   .stl                      STL, binary or ASCII, a mesh (core/io/stl_format.cpp)
//   .xyz .pwn .csv .txt       text columns, a point set (core/io/xyz_format.cpp)
#include <optional>
#include <string>
#include <string_view>

namespace amls {

enum class ShapeFileFormat { ply, off, obj, stl, xyz };

// `text` with its ASCII letters lower-cased.
std::string lower_case(std::string_view text);

// The extension of the file name in `path`, lower-cased, with its dot:
// "scans/Bunny.OFF" -> ".off"; empty when the name has none.
std::string lower_extension(const std::string& path);

// The format `path` names, or nothing for an extension no reader takes.
std::optional<ShapeFileFormat> shape_file_format(const std::string& path);

// Whether `path` names a file read_point_set reads (every format but OBJ and STL, which hold meshes only).
bool is_point_set_file(const std::string& path);

// For messages: the extensions each kind of reader takes.
inline constexpr const char* kShapeFileExtensions = ".ply, .off, .obj, .stl, .xyz, .pwn, .csv or .txt";
inline constexpr const char* kPointSetFileExtensions = ".ply, .off, .xyz, .pwn, .csv or .txt";

}  // namespace amls
