#include "core/io/surface_samples.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/io/mesh_inside.hpp"
#include "core/io/mesh_sampling.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/raw_point_file.hpp"
#include "core/surface/normal_estimation.hpp"
#include "core/surface/broken_normals.hpp"

namespace amls {

namespace {

// Calls fn on `points` held as a set of dimension D: a 2D set as a copy, written back.
template <int D, typename Fn>
auto in_dimension(PointSet<3>& points, Fn&& fn) {
  if constexpr (D == 2) {
    PointSet<2> flat = to_2d(points);
    auto result = fn(flat);
    points = to_3d(flat);
    return result;
  } else {
    return fn(points);
  }
}

template <int D>
NormalEstimation estimate_in(PointSet<3>& points, double radius, ThreadPool& pool) {
  return in_dimension<D>(points, [&](PointSet<D>& set) { return estimate_normals<D>(set, radius, pool); });
}

// Mends the normals that disagree with their neighbours'
// (core/surface/broken_normals.hpp); a warning counts them.
template <int D>
void mend_broken(const std::string& path, PointSet<3>& points, double radius, ThreadPool& pool,
                 std::vector<std::string>& warnings) {
  BrokenNormals broken;
  try {
    broken = in_dimension<D>(points, [&](PointSet<D>& set) {
      return mend_broken_normals<D>(set.positions, set.normals, radius, pool);
    });
  } catch (const std::invalid_argument& e) {  // e.g. a spread too wide for the neighbour index's cells
    throw std::runtime_error(path + ": cannot check the normals against their neighbours': " + e.what());
  }
  if (broken.turned.empty() && broken.replaced.empty()) return;
  const std::size_t first = std::min(broken.turned.empty() ? points.size() : broken.turned.front(),
                                     broken.replaced.empty() ? points.size() : broken.replaced.front());
  std::string where = detail::shortest(points.positions[first].x());
  for (int a = 1; a < D; ++a) {
    where += ' ';
    where += detail::shortest(points.positions[first][a]);
  }
  const std::string turned = std::to_string(broken.turned.size()) + " normals pointed against those of the points "
                             "beside them and were turned over";
  const std::string replaced = std::to_string(broken.replaced.size()) + " normals lay more than " +
                               std::to_string(static_cast<int>(BrokenNormals::kBrokenDegrees)) + " degrees off " +
                               (broken.turned.empty() ? "those of the points beside them" : "theirs") +
                               " and were replaced by their mean direction";
  std::string warning = path + ": ";
  if (!broken.turned.empty()) warning += turned;
  if (!broken.turned.empty() && !broken.replaced.empty()) warning += ", and ";
  if (!broken.replaced.empty()) warning += replaced;
  warning += " (within " + detail::shortest(radius) + "; the first at " + where + ")";
  warnings.push_back(warning);
}

}  // namespace

SurfaceInput read_surface_input(const std::string& path, int dimension) {
  SurfaceInput in;
  in.path = path;
  in.is_mesh = is_mesh_file(path);
  if (in.is_mesh) {
    if (dimension == 2) throw std::runtime_error(path + ": a triangle mesh is a 3D shape, not 2D");
    in.mesh = read_mesh(path);
    if (in.mesh.triangles.empty()) throw std::runtime_error(path + ": the mesh has no faces");
    in.orientation = orient_consistently(in.mesh);
    return in;
  }
  in.point_set = read_point_set(path, dimension);
  if (in.point_set.points.empty()) throw std::runtime_error(path + ": holds no points");
  return in;
}

SurfaceSamples surface_samples(SurfaceInput input, const SurfaceSampleOptions& options) {
  ThreadPool pool(options.threads);
  return surface_samples(std::move(input), options, pool);
}

SurfaceSamples surface_samples(SurfaceInput input, const SurfaceSampleOptions& options, ThreadPool& pool) {
  const std::string& path = input.path;
  SurfaceSamples out;
  if (input.is_mesh) {
    const TriangleMesh& mesh = input.mesh;
    MeshSamples samples;
    try {
      samples = sample_mesh(mesh, options.spacing);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + ": " + e.what());
    }
    out.dimension = 3;
    out.points = std::move(samples.points);
    out.source = "mesh of " + std::to_string(mesh.triangles.size()) + " triangles, sampled at spacing " +
                 std::to_string(options.spacing) + " with face normals";
    if (samples.degenerate_triangles > 0)
      out.warnings.push_back(path + ": " + std::to_string(samples.degenerate_triangles) +
                             " triangles of zero area were skipped");
    if (samples.boundary_edges > 0)
      out.warnings.push_back(path + ": the mesh is open (" + std::to_string(samples.boundary_edges) +
                             " edges belong to one triangle only): its surface has a rim there");
    if (samples.nonmanifold_edges > 0)
      out.warnings.push_back(path + ": " + std::to_string(samples.nonmanifold_edges) +
                             " edges belong to three or more triangles");
    if (input.orientation.turned > 0)
      out.warnings.push_back(path + ": " + std::to_string(input.orientation.turned) + " of " +
                             std::to_string(mesh.triangles.size()) +
                             " triangles were wound against their neighbours and were turned to agree with them");
    if (input.orientation.conflicts > 0)
      out.warnings.push_back(path + ": " + std::to_string(input.orientation.conflicts) +
                             " edges join triangles that no winding makes agree (a one-sided surface)");
    if (samples.flipped)
      out.warnings.push_back(path + ": the faces are wound clockwise seen from outside; normals were flipped outward");
    // Said, so that a user who asked to estimate a mesh's normals knows why nothing changed.
    if (options.estimate_normals)
      out.warnings.push_back(path + ": a mesh's samples take its faces' normals; there are no point normals to set "
                                    "aside and estimate");
    if (closed_and_consistently_wound(mesh)) out.closed_mesh = std::move(input.mesh);
    return out;
  }
  LoadedPointSet& loaded = input.point_set;
  out.warnings = std::move(loaded.warnings);
  out.dimension = loaded.dimension;
  out.points = std::move(loaded.points);
  const bool set_aside = options.estimate_normals && loaded.has_normals;
  if (loaded.has_normals && !set_aside) {
    out.source = "point set of " + std::to_string(out.points.size()) + " points with normals";
    if (options.normal_radius > 0.0) {
      if (out.dimension == 2)
        mend_broken<2>(path, out.points, options.normal_radius, pool, out.warnings);
      else
        mend_broken<3>(path, out.points, options.normal_radius, pool, out.warnings);
    }
    return out;
  }
  if (set_aside)
    for (Vec<3>& normal : out.points.normals) normal.setZero();
  NormalEstimation report;
  try {
    report = out.dimension == 2 ? estimate_in<2>(out.points, options.normal_radius, pool)
                                : estimate_in<3>(out.points, options.normal_radius, pool);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": cannot estimate normals: " + e.what());
  }
  out.source = "point set of " + std::to_string(out.points.size()) +
               (set_aside ? " points with normals, set aside" : " points without normals") +
               "; normals estimated (Pratt fit, oriented over a neighbour graph)";
  for (const std::string& warning : report.warnings) out.warnings.push_back(path + ": " + warning);
  return out;
}

SurfaceSamples load_surface_samples(const std::string& path, const SurfaceSampleOptions& options) {
  return surface_samples(read_surface_input(path, options.dimension), options);
}

}  // namespace amls
