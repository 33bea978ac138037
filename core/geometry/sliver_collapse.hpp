#pragma once
// Slivers of a mesh made by marching simplices, collapsed. Where F is nearly
// zero at a grid vertex, every simplex edge from that vertex that the surface
// crosses puts a mesh vertex right beside it (core/resample/mesh_extraction.hpp
// keeps them at least 1e-3 of the edge away): a cluster of vertices a hair
// apart, whose triangles are slivers of a millionth of the usual area that can
// fold over each other, so that other programs (Open3D's is_watertight) find
// the mesh self-intersecting. Each such cluster - the mesh vertices within
// `reach` h of one grid vertex - is merged into one vertex at their mean (with
// their mean normal), and the triangles that lose an edge go. So no vertex
// moves by more than the cluster's diameter, 2 `reach` h.
//
// A cluster is merged only where that keeps the mesh a closed, oriented
// manifold: afterwards every edge from the merged vertex must be shared by
// exactly two of its triangles, running through it in opposite directions, and
// those triangles must close one fan around it (the link condition). So the
// topology (closed, Euler characteristic) is kept; a cluster that fails the
// test (two sheets of the surface meeting at one grid vertex) is left as it is.
// Clusters are taken in the order of their first vertex, serially: the result
// does not depend on any thread count.
#include <cstddef>

#include "core/geometry/grid.hpp"
#include "core/geometry/surface_mesh.hpp"

namespace amls {

// Half the largest distance, in h, between two vertices merged: a small
// fraction of h, and far above the 1e-3 edge fractions of the slivers. At
// 0.05 a cluster on a flat face at an angle to the grid kept a corner 0.071 h
// out, and the needle it left lay nearly in the plane of a triangle 0.04 h
// away, which Open3D's triangle test took for a crossing (docs/mesh-export.md).
inline constexpr double kSliverReach = 0.08;

// Returns the number of mesh vertices removed by the merges.
std::size_t collapse_slivers(SurfaceMesh<3>& mesh, const Grid<3>& grid, double reach = kSliverReach);

}  // namespace amls
