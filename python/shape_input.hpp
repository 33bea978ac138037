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
  // None (a file's own, or estimated for arrays), "estimated" (a file's own set aside and estimated), or
  // (n, D) for arrays.
  py::object normals;
  int dim = 0;         // files only: 0 from the file, 2 or 3 forces it
  // Arrays only: None or one 0/1 per point (PointSet::rim); a file brings its own marks.
  py::object rim = py::none();
};

// Checks a `dim` argument: 0 (from the file), 2 or 3.
void check_dim(int dim);

// A shape checked with the GIL held: a file's path, or else its arrays as a
// file's contents would be (named "points" in messages, with the rim marks given).
struct PreparedShape {
  std::string path;                     // "" for arrays
  std::optional<SurfaceInput> arrays;  // for arrays
};

// Checks the arguments and sets `opening.estimate_normals` where normals is
// "estimated". Throws std::invalid_argument for a path given with rim marks
// (the file's own marks are the ones its resample keeps) or with a normals
// array (the file brings its own), and for normals neither None, an array
// nor "estimated".
PreparedShape prepare_shape(const ShapeArguments& shape, ShapeOpening& opening);

// The shape opened, from its file or else from its arrays (moved from).
OpenedShape open_input(PreparedShape& shape, const ShapeOpening& opening, ThreadPool& pool);

// Checks the resampling options' ranges, naming the Python arguments:
// spacing and grid (None: 0), radius_factor, threads.
PointSetResampling resampling_options(const py::object& spacing, const py::object& grid, double radius_factor,
                                      const std::string& variant, bool uniform_support, int threads);

}  // namespace amls::python
