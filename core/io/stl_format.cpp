#include "core/io/stl_format.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <vector>

namespace amls::detail {

namespace {

constexpr std::uint64_t kHeaderBytes = 80;
constexpr std::uint64_t kTriangleBytes = 50;
constexpr std::size_t kMaxLine = std::size_t{1} << 20;

// Corners with the same coordinates, bit for bit (-0 as 0), as one vertex.
class VertexWelder {
 public:
  explicit VertexWelder(TriangleMesh& mesh) : mesh_(mesh) {}
  std::uint32_t vertex(const Vec<3>& p) {
    const std::array<std::uint64_t, 3> key{std::bit_cast<std::uint64_t>(p.x() + 0.0),
                                           std::bit_cast<std::uint64_t>(p.y() + 0.0),
                                           std::bit_cast<std::uint64_t>(p.z() + 0.0)};
    const auto [it, added] = index_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::map<std::array<std::uint64_t, 3>, std::uint32_t> index_;
};

std::uint32_t little_endian_u32(const unsigned char* bytes) {
  return std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 | std::uint32_t{bytes[2]} << 16 |
         std::uint32_t{bytes[3]} << 24;
}

float little_endian_float(const unsigned char* bytes) { return std::bit_cast<float>(little_endian_u32(bytes)); }

TriangleMesh read_binary(std::istream& in, std::uint64_t count, const std::string& path) {
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  mesh.triangles.reserve(count);
  std::array<unsigned char, kTriangleBytes> record{};
  for (std::uint64_t t = 0; t < count; ++t) {
    if (!in.read(reinterpret_cast<char*>(record.data()), kTriangleBytes))
      fail(path, "triangle " + std::to_string(t) + ": the file ends early");
    std::array<std::uint32_t, 3> triangle{};
    for (int c = 0; c < 3; ++c) {
      Vec<3> p;
      for (int a = 0; a < 3; ++a) p[a] = little_endian_float(record.data() + 12 + 12 * c + 4 * a);
      if (!p.allFinite()) fail(path, "triangle " + std::to_string(t) + ": a corner with a non-finite coordinate");
      triangle[static_cast<std::size_t>(c)] = welder.vertex(p);
    }
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

// Whether `line` holds a byte no text has (a control byte other than tab or carriage return).
bool has_binary_bytes(std::string_view line) {
  return std::any_of(line.begin(), line.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 && byte != '\t' && byte != '\r';
  });
}

// `not_binary` says why the file was not read as binary, for a file that is not text either.
TriangleMesh read_ascii(std::istream& in, const std::string& path, const std::string& not_binary) {
  TriangleMesh mesh;
  VertexWelder welder(mesh);
  std::string line;
  std::vector<std::string_view> words;
  std::vector<std::uint32_t> corners;
  bool in_facet = false;
  bool solid = false;
  for (std::size_t number = 1; read_line(in, line, kMaxLine, path, number); ++number) {
    auto fail_here = [&](const std::string& what) { fail(path, "line " + std::to_string(number) + ": " + what); };
    if (number == 1) drop_byte_order_mark(line);
    if (has_binary_bytes(line)) fail(path, "neither ASCII STL (binary bytes on line " + std::to_string(number) + ") nor binary STL (" + not_binary + ")");
    split_words(line, words);
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (!solid) {
      if (keyword != "solid") fail_here("expected an STL file: binary, or ASCII starting with 'solid'");
      solid = true;
    } else if (keyword == "facet") {
      if (in_facet) fail_here("'facet' inside a facet (a missing 'endfacet')");
      in_facet = true;
      corners.clear();
    } else if (keyword == "vertex") {
      if (!in_facet) fail_here("'vertex' outside a facet");
      if (words.size() != 4) fail_here("a vertex needs x y z");
      Vec<3> p;
      for (int a = 0; a < 3; ++a) {
        const std::optional<double> value = parse_double(words[static_cast<std::size_t>(a) + 1]);
        if (!value || !std::isfinite(*value))
          fail_here(quoted(words[static_cast<std::size_t>(a) + 1]) + " is not a finite number");
        p[a] = *value;
      }
      corners.push_back(welder.vertex(p));
    } else if (keyword == "endfacet") {
      if (!in_facet) fail_here("'endfacet' outside a facet");
      if (corners.size() != 3)
        fail_here("a facet of " + std::to_string(corners.size()) + " vertices (STL facets are triangles)");
      mesh.triangles.push_back({corners[0], corners[1], corners[2]});
      in_facet = false;
    } else if (keyword == "endsolid") {
      if (in_facet) fail_here("'endsolid' inside a facet");
    } else if (keyword != "outer" && keyword != "endloop" && keyword != "solid") {
      fail_here("unexpected " + quoted(keyword) + " (expected facet, outer loop, vertex, endloop, endfacet)");
    }
  }
  if (!solid) fail(path, "empty file: expected an STL file");
  if (in_facet) fail(path, "the file ends inside a facet");
  return mesh;
}

// Appends `value`'s bytes in little-endian order.
void append_u32(std::string& out, std::uint32_t value) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((value >> (8 * k)) & 0xff);
}
void append_float(std::string& out, float value) { append_u32(out, std::bit_cast<std::uint32_t>(value)); }

}  // namespace

TriangleMesh read_stl(std::istream& in, std::uint64_t file_size, const std::string& path) {
  std::string not_binary = std::to_string(file_size) + " bytes, fewer than a binary STL's header and count";
  if (file_size >= kHeaderBytes + 4) {
    std::array<unsigned char, kHeaderBytes + 4> head{};
    if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) fail(path, "cannot read the header");
    const std::uint64_t count = little_endian_u32(head.data() + kHeaderBytes);
    const std::uint64_t expected = kHeaderBytes + 4 + kTriangleBytes * count;
    if (file_size == expected) return read_binary(in, count, path);
    not_binary = std::to_string(file_size) + " bytes where its count of " + std::to_string(count) +
                 " triangles needs " + std::to_string(expected);
    in.clear();
    in.seekg(0);
  }
  return read_ascii(in, path, not_binary);
}

void write_stl(FileSink& out, const SurfaceMesh<3>& mesh) {
  if (mesh.cells.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(std::to_string(mesh.cells.size()) + " triangles, more than an STL file can count");
  for (const Vec<3>& v : mesh.vertices)
    if ((v.array().abs() > static_cast<double>(std::numeric_limits<float>::max())).any())
      throw std::invalid_argument("a vertex beyond the range of STL's float32 coordinates");
  std::string bytes = "amls surface mesh, " + std::to_string(mesh.cells.size()) + " triangles";
  bytes.resize(kHeaderBytes, ' ');
  append_u32(bytes, static_cast<std::uint32_t>(mesh.cells.size()));
  out.write(bytes);
  for (const auto& cell : mesh.cells) {
    bytes.clear();
    const Vec<3>& a = mesh.vertices[cell[0]];
    const Vec<3>& b = mesh.vertices[cell[1]];
    const Vec<3>& c = mesh.vertices[cell[2]];
    const Vec<3> cross = (b - a).cross(c - a);
    const double length = cross.norm();
    const Vec<3> normal = length > 0.0 ? Vec<3>(cross / length) : Vec<3>::Zero();
    for (int k = 0; k < 3; ++k) append_float(bytes, static_cast<float>(normal[k]));
    for (const std::uint32_t v : cell)
      for (int k = 0; k < 3; ++k) append_float(bytes, static_cast<float>(mesh.vertices[v][k]));
    bytes += std::string(2, '\0');
    out.write(bytes);
  }
}

}  // namespace amls::detail
