#include "python/array_conversion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace amls::python {

namespace {

Array as_array(const py::handle& object, const char* name) {
  if (object.is_none()) throw std::invalid_argument(std::string(name) + ": expected an array, got None");
  // Array casts complex numbers to real ones by dropping their imaginary parts: refused instead.
  const py::array as_given = py::array::ensure(object);
  if (as_given && as_given.dtype().kind() == 'c')
    throw std::invalid_argument(std::string(name) + ": expected real numbers, got complex ones");
  Array a = Array::ensure(object);  // null, with no Python error left set, when it is not numbers
  if (!a) throw std::invalid_argument(std::string(name) + ": expected an array of numbers");
  return a;
}

}  // namespace

int dimension_of(const py::handle& points, const char* name) {
  const Array a = as_array(points, name);
  if (a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3))
    throw std::invalid_argument(std::string(name) + ": expected an (n, 2) or (n, 3) array, got shape " +
                                py::str(py::getattr(points, "shape", py::str("?"))).cast<std::string>());
  return static_cast<int>(a.shape(1));
}

template <int D>
std::vector<Vec<D>> vectors_from(const py::handle& array, const char* name, bool allow_empty) {
  const Array a = as_array(array, name);
  if (a.ndim() != 2 || a.shape(1) != D)
    throw std::invalid_argument(std::string(name) + ": expected an (n, " + std::to_string(D) + ") array, got shape " +
                                py::str(py::getattr(array, "shape", py::str("?"))).cast<std::string>());
  const auto n = static_cast<std::size_t>(a.shape(0));
  if (n == 0 && !allow_empty) throw std::invalid_argument(std::string(name) + ": the array has no rows");
  std::vector<Vec<D>> out(n);
  const double* data = a.data();
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) {
      const double v = data[i * D + static_cast<std::size_t>(k)];
      if (!std::isfinite(v))
        throw std::invalid_argument(std::string(name) + ": row " + std::to_string(i) + " has a non-finite value");
      out[i][k] = v;
    }
  }
  return out;
}

std::vector<std::uint8_t> rim_marks_from(const py::handle& rim, std::size_t count) {
  if (rim.is_none()) return {};
  const Array a = as_array(rim, "rim");
  if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != count)
    throw std::invalid_argument("rim: expected " + std::to_string(count) + " values, one per point, got shape " +
                                py::str(py::getattr(rim, "shape", py::str("?"))).cast<std::string>());
  std::vector<std::uint8_t> marks(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double v = a.data()[i];
    if (v != 0.0 && v != 1.0)
      throw std::invalid_argument("rim: values must be 0 or 1 (or False and True), got " +
                                  py::str(py::float_(v)).cast<std::string>() + " at " + std::to_string(i));
    marks[i] = v == 1.0 ? 1 : 0;
  }
  return marks;
}

template <int D>
py::array_t<bool> rim_marks_of(const PointSet<D>& points) {
  py::array_t<bool> out(static_cast<py::ssize_t>(points.size()));
  bool* data = out.mutable_data();
  for (std::size_t i = 0; i < points.size(); ++i) data[i] = points.on_rim(i);
  return out;
}

template py::array_t<bool> rim_marks_of<2>(const PointSet<2>&);
template py::array_t<bool> rim_marks_of<3>(const PointSet<3>&);

template <int D>
PointSet<D> point_set_from(const py::handle& points, const py::handle& normals) {
  PointSet<D> out;
  out.positions = vectors_from<D>(points, "points");
  if (!normals.is_none()) {
    out.normals = vectors_from<D>(normals, "normals");
    if (out.normals.size() != out.positions.size())
      throw std::invalid_argument("normals: " + std::to_string(out.normals.size()) + " rows for " +
                                  std::to_string(out.positions.size()) + " points");
  }
  return out;
}

template <int D>
std::vector<Vec<D>> positions_from(const py::handle& x, const char* name, bool& single) {
  Array a = as_array(x, name);
  single = a.ndim() == 1;
  if (!single) return vectors_from<D>(x, name, true);
  if (a.shape(0) != D)
    throw std::invalid_argument(std::string(name) + ": expected " + std::to_string(D) + " coordinates, got " +
                                std::to_string(a.shape(0)));
  return vectors_from<D>(a.reshape({py::ssize_t{1}, py::ssize_t{D}}), name);
}

template <int D>
Array to_array(const std::vector<Vec<D>>& vectors) {
  Array out({static_cast<py::ssize_t>(vectors.size()), static_cast<py::ssize_t>(D)});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < vectors.size(); ++i)
    for (int k = 0; k < D; ++k) data[i * D + static_cast<std::size_t>(k)] = vectors[i][k];
  return out;
}

Array to_array(const std::vector<double>& values) {
  Array out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

std::pair<py::object, py::object> points_and_normals(const PointSet<3>& held, int dimension) {
  if (dimension == 2) {
    const PointSet<2> p = to_2d(held);
    return {to_array(p.positions), to_array(p.normals)};
  }
  return {to_array(held.positions), to_array(held.normals)};
}

template <std::size_t K>
py::array_t<std::int64_t> cells_to_array(const std::vector<std::array<std::uint32_t, K>>& cells) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(cells.size()), static_cast<py::ssize_t>(K)});
  std::int64_t* data = out.mutable_data();
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (std::size_t k = 0; k < K; ++k) data[i * K + k] = cells[i][k];
  return out;
}

template std::vector<Vec<2>> vectors_from<2>(const py::handle&, const char*, bool);
template std::vector<Vec<3>> vectors_from<3>(const py::handle&, const char*, bool);
template PointSet<2> point_set_from<2>(const py::handle&, const py::handle&);
template PointSet<3> point_set_from<3>(const py::handle&, const py::handle&);
template std::vector<Vec<2>> positions_from<2>(const py::handle&, const char*, bool&);
template std::vector<Vec<3>> positions_from<3>(const py::handle&, const char*, bool&);
template Array to_array<2>(const std::vector<Vec<2>>&);
template Array to_array<3>(const std::vector<Vec<3>>&);
template py::array_t<std::int64_t> cells_to_array<2>(const std::vector<std::array<std::uint32_t, 2>>&);
template py::array_t<std::int64_t> cells_to_array<3>(const std::vector<std::array<std::uint32_t, 3>>&);

}  // namespace amls::python
