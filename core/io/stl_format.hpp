#pragma once
// STL, the triangle soup of 3D printing, read as a mesh and written from one.
//
// - Reading: binary (an 80-byte header, a 32-bit little-endian triangle
//   count, then 50 bytes a triangle: a normal, three corners as float32 x y
//   z, two attribute bytes) when the file's size is exactly what its count
//   says, else ASCII (`solid`, then `facet normal ... outer loop`, three
//   `vertex x y z`, `endloop endfacet`, ..., `endsolid`; some binary files
//   begin with "solid" too, hence the size test first). The facets' normals
//   are ignored: the corners' order says which side is outside, as in the
//   other mesh formats. STL gives every triangle its own corners; corners
//   with the same coordinates, bit for bit, are merged into one vertex, so
//   that a closed mesh reads as closed.
// - Writing: binary, the corners as float32 (the format's precision), each
//   facet's normal from its corners.
// Errors throw std::runtime_error naming the file, and the line (ASCII) or
// the triangle (binary).
#include <cstdint>
#include <istream>
#include <string>

#include "core/geometry/surface_mesh.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/raw_point_file.hpp"

namespace amls::detail {

TriangleMesh read_stl(std::istream& in, std::uint64_t file_size, const std::string& path);

void write_stl(FileSink& out, const SurfaceMesh<3>& mesh);

}  // namespace amls::detail
