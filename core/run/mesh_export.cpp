#include "core/run/mesh_export.hpp"

#include <optional>
#include <stdexcept>

#include "core/io/mesh_inside.hpp"
#include "core/io/mesh_writer.hpp"

namespace amls {

namespace {

std::string count(std::size_t n, const char* what) { return std::to_string(n) + " " + what; }

template <int D>
MeshExport write_extracted(const std::string& path, const ExtractedMesh<D>& extracted) {
  if (extracted.mesh.cells.empty())
    throw std::runtime_error(path +
                             ": not written: the surface crosses no grid edge near the points (F is "
                             "undefined or of one sign there; are the points too sparse for h?)");
  write_surface_mesh(path, extracted.mesh);
  MeshExport out;
  out.dimension = D;
  out.vertices = extracted.mesh.vertices.size();
  out.cells = extracted.mesh.cells.size();
  out.topology = mesh_topology(extracted.mesh);
  out.stats = extracted.stats;
  return out;
}

}  // namespace

std::string MeshExport::summary() const {
  const bool is_3d = dimension == 3;
  std::string text = count(vertices, "vertices") + ", " + count(cells, is_3d ? "triangles" : "segments");
  if (topology.closed()) return text + ", closed";
  if (topology.boundary > 0) text += ", " + count(topology.boundary, is_3d ? "boundary edges" : "open ends");
  if (topology.non_manifold > 0)
    text += ", " + count(topology.non_manifold, is_3d ? "edges of more than two triangles" : "branching vertices");
  if (topology.misoriented > 0) text += ", " + count(topology.misoriented, "facets with clashing orientations");
  return text;
}

template <int D>
MeshExport export_surface_mesh(const std::string& path, const AmlsSurface<D>& surface, Variant variant,
                               ThreadPool& pool) {
  mesh_format_from_extension(path);
  return write_extracted(path, extract_mesh(surface, variant, pool));
}

template <int D>
MeshExport export_surface_mesh(const std::string& path, const PointSet<D>& points, const Grid<D>& grid,
                               const AmlsParameters& parameters, Variant variant, int threads,
                               const KnownSide<D>& known_side) {
  mesh_format_from_extension(path);
  ThreadPool pool(threads);
  return write_extracted(path, extract_mesh(points, grid, parameters, variant, pool, known_side));
}

template <int D>
MeshExport export_surface_mesh(const std::string& path, const PointSet<D>& points, const Grid<D>& grid,
                               const AmlsParameters& parameters, Variant variant, int threads,
                               const TriangleMesh* closed_input) {
  KnownSide<D> side;
  std::optional<MeshInside> inside;
  if constexpr (D == 3)
    if (closed_input) {
      inside.emplace(*closed_input);
      side = [&inside](const Vec<3>& vertex) { return inside->inside(vertex); };
    }
  return export_surface_mesh(path, points, grid, parameters, variant, threads, side);
}

template <int D>
MeshExport export_resampled_mesh(const std::string& path, const ResampledPointSet<D>& resampled,
                                 const PointSetResampling& options, const TriangleMesh* closed_input) {
  return export_surface_mesh(path, resampled.points, resampled.grid, AmlsParameters{options.radius_factor},
                             options.variant, options.threads, closed_input);
}

template MeshExport export_surface_mesh<2>(const std::string&, const AmlsSurface<2>&, Variant, ThreadPool&);
template MeshExport export_surface_mesh<3>(const std::string&, const AmlsSurface<3>&, Variant, ThreadPool&);
template MeshExport export_surface_mesh<2>(const std::string&, const PointSet<2>&, const Grid<2>&,
                                           const AmlsParameters&, Variant, int, const KnownSide<2>&);
template MeshExport export_surface_mesh<3>(const std::string&, const PointSet<3>&, const Grid<3>&,
                                           const AmlsParameters&, Variant, int, const KnownSide<3>&);
template MeshExport export_surface_mesh<2>(const std::string&, const PointSet<2>&, const Grid<2>&,
                                           const AmlsParameters&, Variant, int, const TriangleMesh*);
template MeshExport export_surface_mesh<3>(const std::string&, const PointSet<3>&, const Grid<3>&,
                                           const AmlsParameters&, Variant, int, const TriangleMesh*);
template MeshExport export_resampled_mesh<2>(const std::string&, const ResampledPointSet<2>&,
                                             const PointSetResampling&, const TriangleMesh*);
template MeshExport export_resampled_mesh<3>(const std::string&, const ResampledPointSet<3>&,
                                             const PointSetResampling&, const TriangleMesh*);

}  // namespace amls
