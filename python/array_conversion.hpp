#pragma once
// numpy arrays to the core's point sets and back. Every check raises a
// ValueError that names the argument: not an (n, 2) or (n, 3) array of
// numbers, no rows, a non-finite value, normals of another shape than the
// points. Arrays are copied (as float64), so the caller's stay untouched.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/io/point_set_io.hpp"

namespace amls::python {

namespace py = pybind11;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The columns of `points` (2 or 3), after checking its shape.
int dimension_of(const py::handle& points, const char* name);

// An (n, D) array as vectors; `name` is the argument's, for messages.
template <int D>
std::vector<Vec<D>> vectors_from(const py::handle& array, const char* name, bool allow_empty = false);

// Points and, unless `normals` is None, their normals (else none: an empty
// normal array).
template <int D>
PointSet<D> point_set_from(const py::handle& points, const py::handle& normals);

// Rim marks (PointSet::rim) from None (none) or a 1-D array of `count`
// values, each 0 or 1 (or False and True).
std::vector<std::uint8_t> rim_marks_from(const py::handle& rim, std::size_t count);

// The marks of `points` as a bool array (n,), all False where it has none.
template <int D>
py::array_t<bool> rim_marks_of(const PointSet<D>& points);

// One position (D,) or many (m, D): the vectors, and whether it was one.
template <int D>
std::vector<Vec<D>> positions_from(const py::handle& x, const char* name, bool& single);

template <int D>
Array to_array(const std::vector<Vec<D>>& vectors);

// A set of either dimension held in 3D (z = 0 in 2D), as results cross from the released work.
template <int D>
PointSet<3> held_in_3d(const PointSet<D>& points) {
  if constexpr (D == 2) {
    return to_3d(points);
  } else {
    return points;
  }
}

Array to_array(const std::vector<double>& values);

// A set held in 3D as the arrays of its dimension: positions and normals, (n, 2) or (n, 3).
std::pair<py::object, py::object> points_and_normals(const PointSet<3>& held, int dimension);

// (m, 3) int64 triangles, or (m, 2) segments.
template <std::size_t K>
py::array_t<std::int64_t> cells_to_array(const std::vector<std::array<std::uint32_t, K>>& cells);

}  // namespace amls::python
