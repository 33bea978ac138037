#pragma once
// Opening a shape file: the one road from a file to oriented samples and the
// h to resample them at, taken by `amls resample` and by the editor (docs/cli.md,
// docs/editor.md). In order:
//   1. read: a point set, its small defects repaired with warnings
//      (core/io/point_set_io.hpp), or a triangle mesh;
//   2. h: `resampling.spacing` or `resampling.grid` when given, else the rule
//      of core/geometry/sample_spacing.hpp (the spacing the file records, else
//      the grid lines its points lie on, else their 4th neighbours), on the
//      file's points (a mesh: its vertices), and for a point set whose
//      points scatter across the surface by more than they lie apart (a
//      noisy raw scan) at least 4 times that scatter
//      (core/geometry/surface_scatter.hpp); a resampling at h is then checked
//      against the cost limits (check_resampling_cost);
//   3. samples: a mesh sampled at h with face normals; a point set without
//      normals (or with `estimate_normals`) gets them estimated over
//      Delta = radius_factor h and oriented (core/surface/normal_estimation.hpp),
//      one with normals has its broken ones mended over Delta
//      (core/surface/broken_normals.hpp) - the editor opens what the command
//      line opens.
// Every warning names the file.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/io/surface_samples.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct ShapeOpening {
  // spacing or grid (else the rule), radius_factor (the normals' fit radius), the cost limits.
  PointSetResampling resampling;
  int dimension = 0;  // 0: from the file; 2 or 3 forces it
  // A point set's own normals set aside and estimated (SurfaceSampleOptions::estimate_normals).
  bool estimate_normals = false;
  // h rounded to this many significant digits (0: as it is) before the samples are made
  // with it: the editor's, whose saved scenes write h to 3 digits.
  int spacing_digits = 0;
  // Called before each step, with its name, index and the count (for a progress display).
  std::function<void(const char* step, int index, int count)> step;
};

struct OpenedShape {
  int dimension = 3;
  PointSet<3> points;           // oriented samples; a 2D set has z = 0 and nz = 0
  SpacingChoice spacing;        // h and why
  std::size_t file_points = 0;  // the points the file holds (a mesh: its vertices)
  std::string source;           // what was read and done: "point set of 5210 points without normals; ..."
  std::vector<std::string> warnings;
  std::optional<TriangleMesh> closed_mesh;  // SurfaceSamples::closed_mesh
};

// The steps open_shape_file() reports, in order.
inline constexpr int kShapeOpeningSteps = 3;

// Throws std::runtime_error naming the file for one that cannot be read or
// holds no points (FileError where the system refused it) or normals that
// cannot be estimated; std::invalid_argument naming it for no h (too few
// distinct points: "give --spacing or --grid") or a resampling at h past the
// cost limits (values out of range); Cancelled when `pool`'s cancel check says stop (before each step,
// and inside the normal estimation).
OpenedShape open_shape_file(const std::string& path, const ShapeOpening& options, ThreadPool& pool);

// Steps 2 and 3 for a shape already read (or made in memory, as the Python
// module's arrays are: `input.path` names it in messages).
OpenedShape open_shape(SurfaceInput input, const ShapeOpening& options, ThreadPool& pool);

}  // namespace amls
