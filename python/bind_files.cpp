// read, write, read_mesh: the core's readers and writers (core/io).
#include <pybind11/stl/filesystem.h>  // paths as str or os.PathLike, as resample and Surface take them

#include <filesystem>

#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "python/array_conversion.hpp"
#include "python/bindings.hpp"
#include "python/released_work.hpp"
#include "python/shape_input.hpp"

namespace amls::python {

namespace {

py::object normals_or_none(const PointSet<3>& points, bool has_normals, int dimension) {
  if (!has_normals) return py::none();
  return dimension == 2 ? py::object(to_array(to_2d(points).normals)) : py::object(to_array(points.normals));
}

py::tuple read_file(const std::filesystem::path& file, int dim, bool with_rim) {
  const std::string path = file.string();
  check_dim(dim);
  LoadedPointSet loaded;
  run_released([&] { loaded = read_file_contents([&] { return read_point_set(path, dim); }); });
  warn_all(loaded.warnings);
  py::object positions = loaded.dimension == 2 ? py::object(to_array(to_2d(loaded.points).positions))
                                               : py::object(to_array(loaded.points.positions));
  py::object normals = normals_or_none(loaded.points, loaded.has_normals, loaded.dimension);
  if (with_rim) return py::make_tuple(positions, normals, rim_marks_of(loaded.points));
  return py::make_tuple(positions, normals);
}

template <int D>
void write_set(const std::string& path, const py::handle& points, const py::handle& normals, double spacing,
               const py::handle& rim) {
  PointSet<D> set = point_set_from<D>(points, normals);
  set.rim = rim_marks_from(rim, set.size());
  const PointFileFormat format = format_from_extension(path);
  run_released([&] { write_point_set(path, set, format, spacing); });
}

void write_file(const std::filesystem::path& file, const py::handle& points, const py::handle& normals,
                double spacing, const py::handle& rim) {
  const std::string path = file.string();
  if (dimension_of(points, "points") == 2) {
    write_set<2>(path, points, normals, spacing, rim);
  } else {
    write_set<3>(path, points, normals, spacing, rim);
  }
}

py::tuple read_mesh_file(const std::filesystem::path& file) {
  const std::string path = file.string();
  TriangleMesh mesh;
  run_released([&] { mesh = read_file_contents([&] { return read_mesh(path); }); });
  return py::make_tuple(to_array(mesh.vertices), cells_to_array(mesh.triangles));
}

}  // namespace

void bind_files(py::module_& m) {
  m.def("read", &read_file, py::arg("path"), py::arg("dim") = 0, py::kw_only(), py::arg("with_rim") = false,
        R"(read(path, dim=0, *, with_rim=False) -> (points, normals) or (points, normals, rim)

Reads a point set, as `amls resample` does: PLY (ASCII, binary little and big endian), OFF, and text
columns (.xyz, .pwn, .csv, .txt); the extension picks the format. The vertices of a PLY or OFF mesh
are read as points (read_mesh reads the faces too).

  path      the file (str or os.PathLike)
  dim       2 or 3 forces the dimension; 0 (default): the file's `amls dim` comment, else 2 when
            every z is 0 (with a warning), else 3
  with_rim  also return the rim marks: the PLY property `rim` that `amls resample` writes where
            an open surface's rim is, so that write(..., rim=) and resample(..., rim=) keep them

Returns points, a float64 array (n, 3) or (n, 2), and normals of the same shape, or None when the
file has none; with with_rim, also rim, a bool array (n,), True where a point is marked (all False
when the file has no marks). Small defects are repaired with a warning (UserWarning), as on the
command line: non-finite points dropped, duplicates merged, bad normals re-estimated.
Raises FileNotFoundError for a missing file, IsADirectoryError for a directory, OSError for one
that cannot be read or parsed (the message names the file and the line or vertex), ValueError for
an extension no reader takes.)");
  m.def("write", &write_file, py::arg("path"), py::arg("points"), py::arg("normals") = py::none(),
        py::arg("spacing") = 0.0, py::arg("rim") = py::none(),
        R"(write(path, points, normals=None, spacing=0.0, rim=None)

Writes a point set as `amls resample --out` does: `.ply` (binary little endian, doubles) or `.xyz`
(shortest decimals that read back bit for bit). A 2D set (n, 2) is written with z = 0 and an
`amls dim 2` comment.

  points    float64 array (n, 3) or (n, 2)
  normals   the same shape, or None to write none
  spacing   > 0: the grid spacing h the points were made at, recorded as `amls spacing h` so that
            reading the file back chooses the same h (resample's report gives it as "h")
  rim       None, or one value per point, True (1) where the point is on an open surface's rim
            (Surface.rim): a .ply file keeps the marks, so that resampling it keeps its rim; a
            .xyz file has no room for them

The file is written through a temporary file renamed over `path`. Raises ValueError for bad arrays
(shape, non-finite or complex values, a zero normal among others) or an unknown extension, OSError
when the file cannot be written (FileNotFoundError for a missing folder, IsADirectoryError for a
directory in the way).)");
  m.def("read_mesh", &read_mesh_file, py::arg("path"),
        R"(read_mesh(path) -> (vertices, faces)

Reads a triangle mesh: OBJ, or PLY or OFF with faces (polygons fan-triangulated). Returns vertices,
float64 (n, 3), and faces, int64 (m, 3) (0-based indices); a file without faces gives no faces.
Raises FileNotFoundError for a missing file, IsADirectoryError for a directory, OSError for one
that cannot be read, ValueError for an extension no mesh reader takes.)");
}

}  // namespace amls::python
