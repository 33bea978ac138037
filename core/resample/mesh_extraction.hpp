#pragma once
// The zero set of F as a mesh (3D: triangles, 2D: a polyline), by marching
// simplices over the grid cubes the surface crosses.
//
// Each cube is split into D! simplices along its main diagonal (Kuhn's
// triangulation: simplex pi runs from the cube's lowest corner along the axes
// in the order pi). A face shared by two cubes is split the same way from
// either side, so the mesh has no cracks, and a simplex has no ambiguous case:
// its corners' signs (a zero counts as positive, as in the resampler) give at
// most two triangles or one segment. Every mesh vertex lies on a simplex edge
// between corners of opposite signs, one vertex per edge, shared by every
// simplex that has the edge, so no vertex is duplicated. It is placed at F's
// root on the edge (Variant::exact, the resampler's root finder) or at the
// zero of the linear interpolant of the corner values (Variant::interpolated),
// but at least 1e-3 of the edge from either end (so that a surface through a
// grid vertex leaves no vertices in one place nor triangles of no area), and
// carries the fitted gradient's unit normal there. In 3D, the vertices that
// a grid vertex where F is nearly zero gathers within 0.05 h are then merged
// into one (core/geometry/sliver_collapse.hpp), so that the slivers between
// them do not fold over each other.
//
// F at the cube corners comes from Resampler::update_function(), which
// evaluates it at the vertices around every point; corners outside those are
// evaluated here. The cubes meshed are those holding a point whose corners
// change sign, and, from them, every cube across a face whose corners change
// sign: the whole zero set around the points, followed to where F is
// undefined. A cube with a corner where F is undefined is left out, so the
// mesh has a boundary there (mesh_topology() counts it), never a patch --
// unless the caller says which side each grid vertex lies on (KnownSide).
#include <cstddef>
#include <functional>

#include "core/geometry/surface_mesh.hpp"
#include "core/resample/resampler.hpp"
#include "core/surface/amls_surface.hpp"

namespace amls {

struct MeshExtractionStats {
  std::size_t undefined_cubes = 0;    // cubes the surface enters that have a corner where F is undefined
  std::size_t extra_evaluations = 0;  // corners evaluated beyond those of update_function()
  std::size_t root_fallbacks = 0;     // exact roots that met an undefined F and took the interpolant's zero
  std::size_t collapsed_vertices = 0;  // 3D: vertices merged into a neighbour beside a grid vertex (sliver_collapse.hpp)
  std::size_t overruled_signs = 0;     // grid vertices where F is defined but of the other side than KnownSide's
};

// Which side of the surface a grid vertex lies on: true inside (negative),
// false outside. Given only where the caller knows it: for the samples of a
// closed input mesh, the mesh's own inside (core/io/mesh_inside.hpp). It then
// decides the sign of every grid vertex the mesh visits, and F only where on
// an edge the crossing lies. Without it, where two sides of a thin or sharply
// folded part come within Delta, the orientation filter makes F jump in sign
// between them; such a jump goes on, away from the points, until F is
// undefined, so a closed input's mesh opened there (12 boundary edges on
// CGAL's elephant.off, 510 on femur.off, nearly all within 2 h of a jump),
// and capped where F ends it left small handles and bubbles
// (docs/mesh-export.md).
template <int D>
using KnownSide = std::function<bool(const Vec<D>& corner)>;

template <int D>
struct ExtractedMesh {
  SurfaceMesh<D> mesh;
  MeshExtractionStats stats;
};

// `surface` must be ready to evaluate (hashed, normals updated).
template <int D>
ExtractedMesh<D> extract_mesh(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool,
                              const KnownSide<D>& known_side = {});

// The mesh of the surface S(P) of `points` (oriented normals) on `grid`.
template <int D>
ExtractedMesh<D> extract_mesh(const PointSet<D>& points, const Grid<D>& grid, const AmlsParameters& parameters,
                              Variant variant, ThreadPool& pool, const KnownSide<D>& known_side = {});

extern template ExtractedMesh<2> extract_mesh<2>(const AmlsSurface<2>&, Variant, ThreadPool&, const KnownSide<2>&);
extern template ExtractedMesh<3> extract_mesh<3>(const AmlsSurface<3>&, Variant, ThreadPool&, const KnownSide<3>&);
extern template ExtractedMesh<2> extract_mesh<2>(const PointSet<2>&, const Grid<2>&, const AmlsParameters&, Variant,
                                                 ThreadPool&, const KnownSide<2>&);
extern template ExtractedMesh<3> extract_mesh<3>(const PointSet<3>&, const Grid<3>&, const AmlsParameters&, Variant,
                                                 ThreadPool&, const KnownSide<3>&);

}  // namespace amls
