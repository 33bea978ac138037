#pragma once
// Triangle meshes from files, as input shapes: OBJ and PLY.
//
// - OBJ: `v x y z` vertices and `f` faces whose corners are `i`, `i/t`,
//   `i//n` or `i/t/n` (only i is used); indices start at 1, and negative ones
//   count back from the last vertex read so far. Polygons are fan-triangulated.
//   Other statements (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are ignored;
//   `#` starts a comment.
// - PLY: the vertex element's x y z and the `face` element's `vertex_indices`
//   (or `vertex_index`) list, ASCII or binary (see point_set_io.hpp).
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

// Reads `.obj` or `.ply` (by extension). A PLY without a face element gives a
// mesh with no triangles (its vertices only); an OBJ without faces likewise.
TriangleMesh read_mesh(const std::string& path);

// Whether `path` names a file that read_mesh reads as a mesh with faces: an
// `.obj`, or a `.ply` whose header declares a face element.
bool is_mesh_file(const std::string& path);

}  // namespace amls
