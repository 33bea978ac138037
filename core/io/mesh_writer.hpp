#pragma once
// Surface meshes (core/geometry/surface_mesh.hpp) to files other programs read:
// Blender, MeshLab, slicers for 3D printing.
//
// - OBJ (`.obj`): `v x y z` and `vn nx ny nz` per vertex; 3D triangles as
//   `f a//a b//b c//c`, 2D segments as `l a b` (indices from 1). Numbers are
//   the shortest decimals that read back as the same doubles.
// - PLY (`.ply`): binary little endian; the vertex element's double x y z
//   nx ny nz, then 3D triangles as the `face` element's `vertex_indices`
//   (uchar count, int indices), 2D segments as the `edge` element's `vertex1
//   vertex2`; an `amls dim N` comment as in point-set files.
// - STL (`.stl`, 3D only): binary, float32 corners (core/io/stl_format.hpp),
//   for slicers that read nothing else; the vertices' normals are not kept.
// A 2D mesh is written with z = 0 and nz = 0. The file is written through a
// temporary file renamed over `path`, as point sets are (point_set_io.hpp).
#include <string>

#include "core/geometry/surface_mesh.hpp"

namespace amls {

enum class MeshFileFormat { obj, ply, stl };

// By extension, in any case. Throws std::invalid_argument naming the path and
// the accepted extensions.
MeshFileFormat mesh_format_from_extension(const std::string& path);

// Throws std::invalid_argument for non-finite values, a normal array of
// another size than the vertices or an index out of range, and
// std::runtime_error naming `path` when the file cannot be written.
void write_surface_mesh(const std::string& path, const SurfaceMesh<2>& mesh);
void write_surface_mesh(const std::string& path, const SurfaceMesh<3>& mesh);

}  // namespace amls
