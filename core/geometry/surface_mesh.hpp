#pragma once
// A surface as a simplicial mesh: triangles in 3D, segments (a polyline) in 2D,
// with one unit normal per vertex. Built by core/resample/mesh_extraction.hpp,
// written by core/io/mesh_writer.hpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
struct SurfaceMesh {
  std::vector<Vec<D>> vertices;
  std::vector<Vec<D>> normals;  // unit, one per vertex, pointing outside
  // 3D: triangles, counter-clockwise seen from outside. 2D: segments from
  // cells[k][0] to cells[k][1], with the outside on the right (a closed curve
  // runs counter-clockwise around the inside).
  std::vector<std::array<std::uint32_t, D>> cells;
};

// How the cells meet at their facets (3D: edges, 2D: vertices). A closed,
// consistently oriented mesh has every facet shared by exactly two cells that
// run through it in opposite directions.
struct MeshTopology {
  std::size_t facets = 0;        // distinct facets
  std::size_t boundary = 0;      // facets of one cell only: where the mesh is open
  std::size_t non_manifold = 0;  // facets of more than two cells
  std::size_t misoriented = 0;   // facets of two cells that run through it the same way
  bool closed() const { return boundary == 0 && non_manifold == 0 && misoriented == 0; }
};

// Throws std::invalid_argument for a cell with an index out of range.
template <int D>
MeshTopology mesh_topology(const SurfaceMesh<D>& mesh);

extern template MeshTopology mesh_topology<2>(const SurfaceMesh<2>&);
extern template MeshTopology mesh_topology<3>(const SurfaceMesh<3>&);

}  // namespace amls
