#pragma once
// A shape given to the module - a file path or arrays - opened as the command
// line opens a file (core/run/shape_opening.hpp): h chosen, missing normals
// estimated, the cost limits checked.
#include <optional>
#include <string>

#include "core/run/shape_opening.hpp"
#include "python/array_conversion.hpp"

namespace amls::python {

struct ShapeArguments {
  py::object points;   // a path (str or os.PathLike), or an (n, D) array
  py::object normals;  // None or (n, D)
  int dim = 0;         // files only: 0 from the file, 2 or 3 forces it
  // Arrays only: None or one 0/1 per point (PointSet::rim); a file brings its own marks.
  py::object rim = py::none();
};

// Checks a `dim` argument: 0 (from the file), 2 or 3.
void check_dim(int dim);

// The file path, or "" for arrays. A path given with rim marks is refused
// (std::invalid_argument): the file's own marks are the ones its resample keeps.
std::string shape_path(const ShapeArguments& shape);

// Checks the arrays (with the GIL held) and returns the shape as a file's
// contents would be, named "points" in messages, with the rim marks given.
SurfaceInput arrays_input(const ShapeArguments& shape);

// The shape opened, from the file at `path` or else from `arrays` (moved from).
OpenedShape open_input(const std::string& path, std::optional<SurfaceInput>& arrays, const ShapeOpening& opening,
                       ThreadPool& pool);

// Checks the resampling options' ranges, naming the Python arguments:
// spacing and grid (None: 0), radius_factor, threads.
PointSetResampling resampling_options(const py::object& spacing, const py::object& grid, double radius_factor,
                                      const std::string& variant, bool uniform_support, int threads);

}  // namespace amls::python
