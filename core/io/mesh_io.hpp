#pragma once
// Triangle meshes from files, as input shapes: OBJ, STL, PLY and OFF.
//
// - OBJ: `v x y z` vertices and `f` faces whose corners are `i`, `i/t`,
//   `i//n` or `i/t/n` (only i is used); indices start at 1, and negative ones
//   count back from the last vertex read so far. Polygons are fan-triangulated.
//   Other statements (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are ignored;
//   `#` starts a comment.
// - PLY: the vertex element's x y z and the `face` element's `vertex_indices`
//   (or `vertex_index`) list, ASCII or binary (see point_set_io.hpp).
// - OFF: the vertices' x y z and the faces' 0-based vertex indices (see
//   core/io/off_format.cpp); polygons are fan-triangulated.
// - STL: binary or ASCII triangles, their equal corners merged (see
//   core/io/stl_format.hpp).
// Errors throw std::runtime_error naming the file and the line or face.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

struct TriangleMesh {
  std::vector<Vec<3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

// Reads `.obj`, `.stl`, `.ply` or `.off` (by extension, in any case). A file
// without faces gives a mesh with no triangles (its vertices only).
TriangleMesh read_mesh(const std::string& path);

// Whether `path` names a file that read_mesh reads as a mesh with faces: an
// `.obj` or `.stl`, or a `.ply` or `.off` whose header declares one or more faces (a
// PLY's `element face 0`, as MeshLab saves point clouds, is a point set).
bool is_mesh_file(const std::string& path);

}  // namespace amls
