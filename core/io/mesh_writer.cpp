#include "core/io/mesh_writer.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "core/io/file_format.hpp"
#include "core/io/raw_point_file.hpp"
#include "core/io/stl_format.hpp"

namespace amls {

namespace {

template <int D>
void check_writable(const std::string& path, const SurfaceMesh<D>& mesh) {
  auto bad = [&](const std::string& what) { throw std::invalid_argument("cannot write " + path + ": " + what); };
  if (mesh.normals.size() != mesh.vertices.size())
    bad(std::to_string(mesh.vertices.size()) + " vertices but " + std::to_string(mesh.normals.size()) + " normals");
  if (mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    bad(std::to_string(mesh.vertices.size()) + " vertices, more than a PLY int index can name");
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite() || !mesh.normals[i].allFinite())
      bad("vertex " + std::to_string(i) + " has a non-finite coordinate or normal");
  for (std::size_t k = 0; k < mesh.cells.size(); ++k)
    for (const std::uint32_t v : mesh.cells[k])
      if (v >= mesh.vertices.size())
        bad("cell " + std::to_string(k) + " names vertex " + std::to_string(v) + " of " +
            std::to_string(mesh.vertices.size()));
}

// A vector as x y z: a 2D one with z = 0.
template <int D>
Vec<3> in_3d(const Vec<D>& v) {
  if constexpr (D == 2) {
    return {v.x(), v.y(), 0.0};
  } else {
    return v;
  }
}

template <int D>
void write_obj(detail::FileSink& sink, const SurfaceMesh<D>& mesh) {
  std::string text = "# amls surface mesh (" + std::to_string(D) + "D): " + std::to_string(mesh.vertices.size()) +
                     " vertices, " + std::to_string(mesh.cells.size()) + (D == 3 ? " triangles\n" : " segments\n");
  sink.write(text);
  auto vector_line = [&](const char* tag, const Vec<3>& v) {
    text.clear();
    text += tag;
    for (int a = 0; a < 3; ++a) {
      text += ' ';
      detail::append_double(text, v[a]);
    }
    text += '\n';
    sink.write(text);
  };
  for (const Vec<D>& v : mesh.vertices) vector_line("v", in_3d<D>(v));
  for (const Vec<D>& n : mesh.normals) vector_line("vn", in_3d<D>(n));
  for (const auto& cell : mesh.cells) {
    text.clear();
    text += D == 3 ? 'f' : 'l';
    for (const std::uint32_t v : cell) {
      const std::string index = std::to_string(std::uint64_t{v} + 1);
      text += ' ' + index;
      if (D == 3) text += "//" + index;
    }
    text += '\n';
    sink.write(text);
  }
}

// Appends `value`'s bytes in little-endian order.
template <typename T>
void append_little_endian(std::string& out, T value) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t,
                                  std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint8_t>>;
  const auto bits = std::bit_cast<Bits>(value);
  for (std::size_t k = 0; k < sizeof(T); ++k) out += static_cast<char>((bits >> (8 * k)) & 0xff);
}

template <int D>
void write_ply(detail::FileSink& sink, const SurfaceMesh<D>& mesh) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment amls dim " + std::to_string(D) +
                      "\nelement vertex " + std::to_string(mesh.vertices.size()) +
                      "\nproperty double x\nproperty double y\nproperty double z\n"
                      "property double nx\nproperty double ny\nproperty double nz\n";
  if constexpr (D == 3) {
    bytes += "element face " + std::to_string(mesh.cells.size()) + "\nproperty list uchar int vertex_indices\n";
  } else {
    bytes += "element edge " + std::to_string(mesh.cells.size()) + "\nproperty int vertex1\nproperty int vertex2\n";
  }
  bytes += "end_header\n";
  sink.write(bytes);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    bytes.clear();
    const Vec<3> p = in_3d<D>(mesh.vertices[i]), n = in_3d<D>(mesh.normals[i]);
    for (int a = 0; a < 3; ++a) append_little_endian(bytes, p[a]);
    for (int a = 0; a < 3; ++a) append_little_endian(bytes, n[a]);
    sink.write(bytes);
  }
  for (const auto& cell : mesh.cells) {
    bytes.clear();
    if constexpr (D == 3) append_little_endian(bytes, std::uint8_t{3});
    for (const std::uint32_t v : cell) append_little_endian(bytes, static_cast<std::int32_t>(v));
    sink.write(bytes);
  }
}

template <int D>
void write_mesh(const std::string& path, const SurfaceMesh<D>& mesh) {
  const MeshFileFormat format = mesh_format_from_extension(path);
  check_writable(path, mesh);
  if constexpr (D == 2) {
    if (format == MeshFileFormat::stl)
      throw std::invalid_argument("cannot write " + path + ": an STL file holds triangles, and a 2D mesh is segments "
                                  "(write .obj or .ply)");
  } else if (format == MeshFileFormat::stl) {
    try {
      detail::write_through_temporary(path, [&](detail::FileSink& sink) { detail::write_stl(sink, mesh); });
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("cannot write " + path + ": " + e.what());
    }
    return;
  }
  detail::write_through_temporary(path, [&](detail::FileSink& sink) {
    if (format == MeshFileFormat::obj) {
      write_obj(sink, mesh);
    } else {
      write_ply(sink, mesh);
    }
  });
}

}  // namespace

MeshFileFormat mesh_format_from_extension(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return MeshFileFormat::obj;
  if (extension == ".ply") return MeshFileFormat::ply;
  if (extension == ".stl") return MeshFileFormat::stl;
  if (extension.empty())
    throw std::invalid_argument(path + ": no file extension (expected .obj, .ply or .stl for a mesh)");
  throw std::invalid_argument(path + ": unknown mesh file extension '" + extension + "' (expected .obj, .ply or .stl)");
}

void write_surface_mesh(const std::string& path, const SurfaceMesh<2>& mesh) { write_mesh(path, mesh); }
void write_surface_mesh(const std::string& path, const SurfaceMesh<3>& mesh) { write_mesh(path, mesh); }

}  // namespace amls
