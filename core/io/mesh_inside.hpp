#pragma once
// Whether a point lies inside a closed triangle mesh, by its generalized
// winding number (Jacobson, Kavan and Sorkine-Hornung 2013): the solid angle
// the triangles subtend at the point, over 4 pi, is +-1 inside and 0 outside
// (the sign is the faces' winding, so either winding works), and it degrades
// gracefully where the mesh is not quite closed. The mesh export asks it only
// where F is undefined (core/resample/mesh_extraction.hpp, UndefinedSide), a
// few hundred grid vertices a mesh, so it visits every triangle each time.
#include <cmath>

#include "core/io/mesh_io.hpp"

namespace amls {

double winding_number(const TriangleMesh& mesh, const Vec<3>& x);

// Whether the mesh bounds a solid whose inside the winding number gives:
// every edge is run through by exactly two triangles, in opposite directions.
// (A mesh wound every which way, as CGAL's *-shuffled.off are, is not: its
// winding number is neither 0 nor +-1 around it.)
bool closed_and_consistently_wound(const TriangleMesh& mesh);

inline bool inside_mesh(const TriangleMesh& mesh, const Vec<3>& x) { return std::abs(winding_number(mesh, x)) > 0.5; }

}  // namespace amls
