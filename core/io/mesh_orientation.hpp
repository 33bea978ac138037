#pragma once
// A triangle mesh's faces wound consistently: two triangles that share an
// edge run through it in opposite directions.
//
// Files from some tools (CGAL's "-shuffled" meshes, polygon soups stitched
// together) wind their faces either way. Sampled as they are, half of the
// face normals point inward, F changes sign along the surface, and a closed
// mesh comes out with holes; nor does such a mesh have an inside to cap the
// export with. So each part of the mesh (triangles joined across edges that
// exactly two of them share) is wound as its seed is, triangle by triangle
// outward from it, and then turned as a whole if that turned more than half
// of its triangles: the winding most of the file's triangles already had.
// A consistently wound mesh is left as it is. An edge of three or more
// triangles joins nothing; a one-sided part (a Moebius strip) cannot be
// wound consistently, and its edges against the winding are counted.
#include <cstddef>

#include "core/io/mesh_io.hpp"

namespace amls {

struct MeshOrientation {
  std::size_t turned = 0;     // triangles whose corners were reordered
  std::size_t conflicts = 0;  // edges whose two triangles still run through it alike (one-sided parts)
};

MeshOrientation orient_consistently(TriangleMesh& mesh);

}  // namespace amls
