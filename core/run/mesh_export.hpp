#pragma once
// A point set's surface S(P) written as a mesh (`amls resample --mesh`,
// `amls deform --mesh`, the editor's Export mesh): extract_mesh() and
// write_surface_mesh(), with what to tell the user about the result.
#include <string>

#include "core/geometry/surface_mesh.hpp"
#include "core/io/mesh_io.hpp"
#include "core/resample/mesh_extraction.hpp"
#include "core/run/point_set_resampling.hpp"

namespace amls {

struct MeshExport {
  int dimension = 3;
  std::size_t vertices = 0;
  std::size_t cells = 0;  // triangles (3D) or segments (2D)
  MeshTopology topology;
  MeshExtractionStats stats;
  // "20702 vertices, 41400 triangles, closed" or "..., 96 boundary edges"
  // (2D: "segments", "open ends"), with any non-manifold or misoriented facets.
  std::string summary() const;
};

// Checks the path's extension (mesh_format_from_extension) before any work.
// `surface` must be ready to evaluate. Throws std::runtime_error naming the
// path, and writes nothing, when the mesh is empty.
template <int D>
MeshExport export_surface_mesh(const std::string& path, const AmlsSurface<D>& surface, Variant variant,
                               ThreadPool& pool);
template <int D>
MeshExport export_surface_mesh(const std::string& path, const PointSet<D>& points, const Grid<D>& grid,
                               const AmlsParameters& parameters, Variant variant, int threads,
                               const KnownSide<D>& known_side = {});
// The same with the sides taken from `closed_input` (3D: a closed input mesh;
// none: F's signs alone), as export_resampled_mesh below decides them.
template <int D>
MeshExport export_surface_mesh(const std::string& path, const PointSet<D>& points, const Grid<D>& grid,
                               const AmlsParameters& parameters, Variant variant, int threads,
                               const TriangleMesh* closed_input);

// The mesh `amls resample --mesh` writes: the surface of the resampled points
// on the resampling's grid, with its Delta and variant. The editor's Export
// mesh of those points, opened as a file, is the same mesh byte for byte
// (tests/test_editor_worker.cpp), so what is found of one holds for the other.
// With `closed_input` (3D: the input mesh, where it is closed), every grid
// vertex the mesh visits lies on the side the input mesh says (KnownSide,
// core/io/mesh_inside.hpp), so that a closed mesh in gives a closed mesh out
// of the input's topology, with F placing the crossings.
template <int D>
MeshExport export_resampled_mesh(const std::string& path, const ResampledPointSet<D>& resampled,
                                 const PointSetResampling& options, const TriangleMesh* closed_input = nullptr);

extern template MeshExport export_surface_mesh<2>(const std::string&, const AmlsSurface<2>&, Variant, ThreadPool&);
extern template MeshExport export_surface_mesh<3>(const std::string&, const AmlsSurface<3>&, Variant, ThreadPool&);
extern template MeshExport export_surface_mesh<2>(const std::string&, const PointSet<2>&, const Grid<2>&,
                                                  const AmlsParameters&, Variant, int, const KnownSide<2>&);
extern template MeshExport export_surface_mesh<3>(const std::string&, const PointSet<3>&, const Grid<3>&,
                                                  const AmlsParameters&, Variant, int, const KnownSide<3>&);
extern template MeshExport export_surface_mesh<2>(const std::string&, const PointSet<2>&, const Grid<2>&,
                                                  const AmlsParameters&, Variant, int, const TriangleMesh*);
extern template MeshExport export_surface_mesh<3>(const std::string&, const PointSet<3>&, const Grid<3>&,
                                                  const AmlsParameters&, Variant, int, const TriangleMesh*);
extern template MeshExport export_resampled_mesh<2>(const std::string&, const ResampledPointSet<2>&,
                                                    const PointSetResampling&, const TriangleMesh*);
extern template MeshExport export_resampled_mesh<3>(const std::string&, const ResampledPointSet<3>&,
                                                    const PointSetResampling&, const TriangleMesh*);

}  // namespace amls
