#pragma once
// An input shape from a file, as oriented samples: a point set with normals
// (PLY, OFF, text columns; core/io/point_set_io.hpp) as it is; a point set
// without normals with normals estimated (core/surface/normal_estimation.hpp);
// a triangle mesh (OBJ, or PLY or OFF with faces) sampled at about the given
// spacing with face normals (core/io/mesh_sampling.hpp). `amls resample` and scenes read shapes through this.
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"

namespace amls {

struct SurfaceSampleOptions {
  double spacing = 0.0;        // meshes: sample spacing (> 0)
  double normal_radius = 0.0;  // point sets without normals: the fit radius (> 0), e.g. Delta
  int dimension = 0;           // point sets: 0 decides from the file, 2 or 3 forces it
  int threads = 1;
};

struct SurfaceSamples {
  int dimension = 3;
  PointSet<3> points;  // a 2D set has z = 0 and nz = 0
  std::string source;  // what was read and done, for messages: "mesh of 12 triangles, sampled", ...
  std::vector<std::string> warnings;  // each names the file
};

// Throws std::runtime_error naming the file if it cannot be read or holds no
// points (or no triangle of positive area), and for a mesh read as 2D.
SurfaceSamples load_surface_samples(const std::string& path, const SurfaceSampleOptions& options);

}  // namespace amls
