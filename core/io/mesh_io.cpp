#include "core/io/mesh_io.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "core/io/file_format.hpp"
#include "core/io/raw_point_file.hpp"
#include "core/io/stl_format.hpp"
#include "core/util/file_error.hpp"

namespace amls {

namespace {

namespace fs = std::filesystem;
using detail::fail;

constexpr std::size_t kMaxLine = std::size_t{1} << 20;

std::ifstream open_binary(const std::string& path) {
  reject_directory(path, "mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_cannot_open(path, "cannot open");
  return in;
}

std::uint64_t file_size(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) fail(path, "cannot tell its size: " + error.message());
  return size;
}

TriangleMesh read_obj(std::istream& in, const std::string& path) {
  TriangleMesh mesh;
  std::string line;
  std::vector<std::string_view> words;
  std::vector<std::uint32_t> face;
  for (std::size_t number = 1; detail::read_line(in, line, kMaxLine, path, number); ++number) {
    auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(number) + ": " + what); };
    detail::split_words(line, words);
    if (words.empty() || words[0].front() == '#') continue;
    if (words[0] == "v") {
      // x y z, and an optional w (or colour) that is ignored.
      if (words.size() < 4) fail_here("a vertex needs x y z");
      Vec<3> v;
      for (int a = 0; a < 3; ++a) {
        const std::optional<double> value = detail::parse_double(words[static_cast<std::size_t>(a) + 1]);
        if (!value || !std::isfinite(*value))
          fail_here(detail::quoted(words[static_cast<std::size_t>(a) + 1]) + " is not a finite number");
        v[a] = *value;
      }
      mesh.vertices.push_back(v);
    } else if (words[0] == "f") {
      if (words.size() < 4) fail_here("a face needs at least 3 vertices, got " + std::to_string(words.size() - 1));
      face.clear();
      for (std::size_t k = 1; k < words.size(); ++k) {
        const std::string_view corner = words[k].substr(0, words[k].find('/'));
        const std::optional<std::int64_t> index = detail::parse_integer(corner);
        if (!index || *index == 0)
          fail_here(detail::quoted(words[k]) + " is not a vertex index (1-based, or negative)");
        const auto count = static_cast<std::int64_t>(mesh.vertices.size());
        const std::int64_t resolved = *index > 0 ? *index - 1 : count + *index;
        if (resolved < 0 || resolved >= count)
          fail_here("vertex index " + std::to_string(*index) + " is out of range (" + std::to_string(count) +
                    " vertices so far)");
        face.push_back(static_cast<std::uint32_t>(resolved));
      }
      for (std::size_t k = 1; k + 1 < face.size(); ++k) mesh.triangles.push_back({face[0], face[k], face[k + 1]});
    }
  }
  return mesh;
}

}  // namespace

TriangleMesh read_mesh(const std::string& path) {
  reject_directory(path, "mesh file");
  const std::optional<ShapeFileFormat> format = shape_file_format(path);
  if (!format || *format == ShapeFileFormat::xyz)
    throw std::invalid_argument(path + ": unknown mesh file extension '" + lower_extension(path) +
                                "' (expected .obj, .stl, .ply or .off)");
  std::ifstream in = open_binary(path);
  if (*format == ShapeFileFormat::obj) return read_obj(in, path);
  const std::uint64_t size = file_size(path);
  if (*format == ShapeFileFormat::stl) return detail::read_stl(in, size, path);
  detail::RawPointFile raw =
      *format == ShapeFileFormat::ply ? detail::read_ply(in, size, path) : detail::read_off(in, size, path);
  if (!raw.face_problem.empty()) fail(path, raw.face_problem);
  TriangleMesh mesh;
  mesh.vertices = std::move(raw.points.positions);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite()) fail(path, raw.where(i) + ": a vertex with a non-finite coordinate");
  mesh.triangles = std::move(raw.triangles);
  return mesh;
}

bool is_mesh_file(const std::string& path) {
  const std::optional<ShapeFileFormat> format = shape_file_format(path);
  if (!format || *format == ShapeFileFormat::xyz) return false;
  if (*format == ShapeFileFormat::obj || *format == ShapeFileFormat::stl) return true;
  std::ifstream in = open_binary(path);
  return *format == ShapeFileFormat::ply ? detail::ply_face_count(in, path) > 0
                                         : detail::off_face_count(in, file_size(path), path) > 0;
}

}  // namespace amls
