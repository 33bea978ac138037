#include "core/io/mesh_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "core/io/raw_point_file.hpp"

namespace amls {

namespace {

namespace fs = std::filesystem;
using detail::fail;

constexpr std::size_t kMaxLine = std::size_t{1} << 20;

std::string lower_extension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::ifstream open_binary(const std::string& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) fail(path, "is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
  return in;
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
        if (!index || *index == 0) fail_here(detail::quoted(words[k]) + " is not a vertex index (1-based, or negative)");
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
  const std::string extension = lower_extension(path);
  if (extension != ".obj" && extension != ".ply")
    throw std::invalid_argument(path + ": unknown mesh file extension '" + extension + "' (expected .obj or .ply)");
  std::ifstream in = open_binary(path);
  if (extension == ".obj") return read_obj(in, path);
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) fail(path, "cannot tell its size: " + error.message());
  detail::RawPointFile raw = detail::read_ply(in, size, path);
  if (!raw.face_problem.empty()) fail(path, raw.face_problem);
  TriangleMesh mesh;
  mesh.vertices = std::move(raw.points.positions);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite()) fail(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
  mesh.triangles = std::move(raw.triangles);
  return mesh;
}

bool is_mesh_file(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return true;
  if (extension != ".ply") return false;
  std::ifstream in = open_binary(path);
  std::string line;
  for (std::size_t number = 1; detail::read_line(in, line, 1 << 16, path, number); ++number) {
    std::vector<std::string_view> words;
    detail::split_words(line, words);
    if (words.size() >= 2 && words[0] == "element" && words[1] == "face") return true;
    if (!words.empty() && words[0] == "end_header") return false;
  }
  return false;
}

}  // namespace amls
