#pragma once
// An input shape from a file, as oriented samples: a point set with normals
// (PLY, OFF, text columns; core/io/point_set_io.hpp) as it is, but for the
// normals that disagree with their neighbours', which are mended
// (core/surface/broken_normals.hpp); a point set without normals with
// normals estimated (core/surface/normal_estimation.hpp), as is one whose
// normals the caller sets aside;
// a triangle mesh (OBJ, or PLY or OFF with faces) sampled at about the given
// spacing with face normals (core/io/mesh_sampling.hpp). `amls resample` and scenes read shapes through this.
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/mesh_orientation.hpp"
#include "core/io/point_set_io.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct SurfaceSampleOptions {
  double spacing = 0.0;        // meshes: sample spacing (> 0)
  // Point sets: without normals, the fit radius (> 0), e.g. Delta; with
  // normals, the reach of the broken-normal test (0 skips it).
  double normal_radius = 0.0;
  // Point sets: the file's normals set aside and estimated as for a set
  // without, for a file whose normals are unoriented (a face's all pointing
  // inward), which mending one at a time cannot put right.
  bool estimate_normals = false;
  int dimension = 0;           // point sets: 0 decides from the file, 2 or 3 forces it
  int threads = 1;             // the overloads without a pool
};

struct SurfaceSamples {
  int dimension = 3;
  PointSet<3> points;  // a 2D set has z = 0 and nz = 0
  std::string source;  // what was read and done, for messages: "mesh of 12 triangles, sampled", ...
  std::vector<std::string> warnings;  // each names the file
  // The input mesh, where it is closed and consistently wound
  // (closed_and_consistently_wound, core/io/mesh_inside.hpp): its inside is
  // known, which closes the mesh export where F is undefined
  // (core/run/mesh_export.hpp).
  std::optional<TriangleMesh> closed_mesh;
};

// A shape file as read, before it is sampled: a triangle mesh or a point set.
struct SurfaceInput {
  std::string path;
  bool is_mesh = false;
  TriangleMesh mesh;          // when is_mesh, its faces wound consistently (mesh_orientation.hpp)
  MeshOrientation orientation;  // what winding them consistently did
  LoadedPointSet point_set;   // otherwise
  int dimension() const { return is_mesh ? 3 : point_set.dimension; }
  // The positions a spacing is measured on: a mesh's vertices, a point set's points.
  const std::vector<Vec<3>>& positions() const { return is_mesh ? mesh.vertices : point_set.points.positions; }
  // The grid spacing the file records (`amls spacing`, point sets only); 0 if none.
  double recorded_spacing() const { return is_mesh ? 0.0 : point_set.spacing; }
};

// Reads `path` (dimension: 0 decides from the file, 2 or 3 forces it); a
// mesh's faces are wound consistently (orient_consistently) before h is
// chosen on it, as its thickness needs an inside.
// Throws std::runtime_error naming the file if it cannot be read, holds no
// points or is a mesh without faces, and for a mesh read as 2D.
SurfaceInput read_surface_input(const std::string& path, int dimension);

// The samples of a shape read by read_surface_input(), which it takes over
// (options.dimension is the input's). Throws std::runtime_error naming the
// file for a mesh with no triangle of positive area, or normals that cannot
// be estimated or checked (a spread too wide for the neighbour index). Normals are estimated on `pool` (its cancel check stops them
// with Cancelled); the overload without one makes a pool of options.threads.
SurfaceSamples surface_samples(SurfaceInput input, const SurfaceSampleOptions& options, ThreadPool& pool);
SurfaceSamples surface_samples(SurfaceInput input, const SurfaceSampleOptions& options);

// read_surface_input() then surface_samples().
SurfaceSamples load_surface_samples(const std::string& path, const SurfaceSampleOptions& options);

}  // namespace amls
