#pragma once
// Oriented samples of a triangle mesh at about a given spacing, for meshes
// used as input shapes. Deterministic (no random numbers): every vertex once,
// points evenly spaced along every edge, and the interior points of a
// barycentric lattice on every triangle, fine enough that no two neighbours are
// farther apart than the spacing. Points inside a triangle carry its face
// normal; points on an edge or at a vertex the area-weighted mean of the
// normals of the faces around them, normalised.
#include <cstddef>

#include "core/io/mesh_io.hpp"
#include "core/geometry/point_set.hpp"

namespace amls {

struct MeshSamples {
  PointSet<3> points;
  std::size_t degenerate_triangles = 0;  // of zero area (or with a repeated vertex), skipped
  std::size_t boundary_edges = 0;        // edges of one triangle: the mesh is open there
  std::size_t nonmanifold_edges = 0;     // edges of three or more triangles
  // The mesh is closed and its faces were wound clockwise seen from outside
  // (negative enclosed volume), so every normal was flipped to point outward.
  bool flipped = false;
};

// Throws std::invalid_argument for a spacing that is not positive or a mesh
// with no triangle of positive area.
MeshSamples sample_mesh(const TriangleMesh& mesh, double spacing);

}  // namespace amls
