#include "python/shape_input.hpp"

#include "core/io/point_set_io.hpp"
#include "core/util/parameter_ranges.hpp"
#include "python/released_work.hpp"

namespace amls::python {

void check_dim(int dim) {
  if (dim != 0 && dim != 2 && dim != 3) throw std::invalid_argument("dim: must be 0 (from the file), 2 or 3");
}

namespace {

// Whether the normals argument is the string "estimated" (any other string is refused).
bool estimated(const py::object& normals) {
  if (!py::isinstance<py::str>(normals)) return false;
  const std::string text = normals.cast<std::string>();
  if (text != "estimated")
    throw std::invalid_argument("normals: expected None, an array of unit normals or \"estimated\", got \"" + text +
                                "\"");
  return true;
}

SurfaceInput arrays_input(const ShapeArguments& shape, bool estimate) {
  SurfaceInput input;
  input.path = "points";
  LoadedPointSet& loaded = input.point_set;
  loaded.dimension = dimension_of(shape.points, "points");
  loaded.has_normals = !shape.normals.is_none() && !estimate;
  const py::object normals = loaded.has_normals ? shape.normals : py::none();
  loaded.points = loaded.dimension == 2 ? to_3d(point_set_from<2>(shape.points, normals))
                                        : point_set_from<3>(shape.points, normals);
  // Without normals the set holds zero ones, as a file without normals reads.
  if (!loaded.has_normals) loaded.points.normals.assign(loaded.points.size(), Vec<3>::Zero());
  loaded.points.rim = rim_marks_from(shape.rim, loaded.points.size());
  return input;
}

}  // namespace

PreparedShape prepare_shape(const ShapeArguments& shape, ShapeOpening& opening) {
  opening.estimate_normals = estimated(shape.normals);
  PreparedShape out;
  const py::object os_path = py::module_::import("os").attr("PathLike");
  if (!py::isinstance<py::str>(shape.points) && !py::isinstance(shape.points, os_path)) {
    out.arrays = arrays_input(shape, opening.estimate_normals);
    return out;
  }
  if (!shape.rim.is_none())
    throw std::invalid_argument("rim: only for arrays; a file's own marks (the PLY property rim) are used");
  if (!shape.normals.is_none() && !opening.estimate_normals)
    throw std::invalid_argument(
        "normals: only for arrays; a file brings its own (None), or \"estimated\" sets them aside and estimates "
        "them");
  out.path = py::str(py::module_::import("os").attr("fspath")(shape.points)).cast<std::string>();
  return out;
}

OpenedShape open_input(PreparedShape& shape, const ShapeOpening& opening, ThreadPool& pool) {
  if (shape.path.empty()) return open_shape(std::move(*shape.arrays), opening, pool);
  pool.poll_cancel();
  return open_shape(read_file_contents([&] { return read_surface_input(shape.path, opening.dimension); }), opening,
                    pool);
}

PointSetResampling resampling_options(const py::object& spacing, const py::object& grid, double radius_factor,
                                      const std::string& variant, bool uniform_support, int threads) {
  PointSetResampling r;
  if (!spacing.is_none() && !grid.is_none()) throw std::invalid_argument("spacing and grid: give one, not both");
  if (!spacing.is_none()) {
    r.spacing = spacing.cast<double>();
    check_range("spacing", r.spacing, ranges::kSpacing);
  }
  if (!grid.is_none()) {
    const double cells = grid.cast<double>();
    check_range("grid", cells, ranges::kGridCells);
    r.grid = static_cast<int>(cells);
    if (r.grid != cells)
      throw std::invalid_argument("grid: must be a whole number of cells, got " + format_number(cells));
  }
  check_range("radius_factor", radius_factor, ranges::kRadiusFactor);
  check_range("threads", threads, ranges::kThreads);
  r.radius_factor = radius_factor;
  r.variant = parse_variant(variant);
  r.widen_support = !uniform_support;
  r.threads = threads;
  return r;
}

}  // namespace amls::python
