#pragma once
// What the editor computes its surface with, and where the initial shape came
// from (as a scene says it: docs/scene-format.md on the scenes branch). No GL.
#include <cstddef>
#include <string>
#include <vector>

#include "core/mls_deformation.hpp"
#include "core/point_set.hpp"
#include "core/resampler.hpp"

namespace amls::editor {

struct SurfaceSettings {
  double spacing = 0.024;      // grid spacing h
  double radius_factor = 3.0;  // Delta / h
  Variant variant = Variant::exact;
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
  bool resample = true;  // resample after every deformation step (off: watch S(P) break)

  bool operator==(const SurfaceSettings&) const = default;
  // Whether the grid (h, Delta / h) differs, which needs a new surface.
  bool same_grid(const SurfaceSettings& o) const { return spacing == o.spacing && radius_factor == o.radius_factor; }
};

// Throws std::invalid_argument naming the first field out of range.
void validate(const SurfaceSettings& settings);

// The initial shape as a scene's `shape` object says it.
struct ShapeSource {
  enum class Type { circle, sphere, file };
  Type type = Type::circle;
  Vec<3> center = Vec<3>::Zero();  // circle, sphere (z unused in 2D)
  double radius = 1.0;             // circle, sphere
  std::size_t points = 0;          // circle, sphere
  std::string path;                // file: as opened (absolute or relative to the working directory)
};

// Everything a session starts from.
struct InitialShape {
  int dimension = 2;
  PointSet<3> points;  // oriented; 2D sets have z = 0 and nz = 0
  ShapeSource source;
  SurfaceSettings settings;
  std::vector<Vec<3>> handles;  // handles to start with (a scene's first stage)
  std::string name;             // shown in the title and messages
  std::vector<std::string> warnings;
};

}  // namespace amls::editor
