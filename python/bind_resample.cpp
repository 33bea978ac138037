// resample and mesh: `amls resample` on arrays (core/run/point_set_resampling,
// core/run/mesh_export), with its defaults, checks and report.
#include <optional>

#include "core/io/mesh_writer.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/resampling_report.hpp"
#include "core/util/process_memory.hpp"
#include "core/util/stopwatch.hpp"
#include "python/bindings.hpp"
#include "python/released_work.hpp"
#include "python/shape_input.hpp"

namespace amls::python {

namespace {

// What one call did, handed from the released work back to Python.
struct Resampled {
  int dimension = 3;
  PointSet<3> points;
  std::string report;  // JSON text
  bool clear_loss = false;
  std::string loss_message;
  std::vector<std::string> warnings;
};

template <int D>
void resample_opened(const OpenedShape& shape, const std::string& input, PointSetResampling options,
                     const std::string& mesh_path, Stopwatch& clock, Resampled& out) {
  const PointSet<D> points = from_3d<D>(shape.points);
  const ResampledPointSet<D> result = resample_point_set(points, options);
  require_resampled_points(result, options);
  ResamplingRun run;
  run.input = input;
  run.file_points = shape.file_points;
  run.points_in = points.size();
  run.seconds = clock.lap();
  run.peak_memory_mib = peak_memory_mib();
  // As `amls resample --mesh` writes it (a closed input mesh gives a closed mesh).
  if (!mesh_path.empty())
    export_resampled_mesh(mesh_path, result, options, shape.closed_mesh ? &*shape.closed_mesh : nullptr);
  out.dimension = D;
  out.points = held_in_3d(result.points);
  out.report = resampling_report_json(result, options, run).dump();
  out.clear_loss = result.coverage.clear_loss();
  if (out.clear_loss)
    out.loss_message = (input.empty() ? std::string("points") : input) + ": " + result.coverage.loss_message();
}

// Opens the shape (h chosen, normals estimated) on the released thread.
py::tuple resample(py::object points, py::object normals, py::object spacing, py::object grid, double radius_factor,
                   const std::string& variant, bool uniform_support, bool accept_loss, int dim, int threads,
                   const std::string& mesh, py::object rim, bool one_pass, bool with_rim, bool rims) {
  Stopwatch clock;
  const ShapeArguments shape{std::move(points), std::move(normals), dim, std::move(rim)};
  ShapeOpening opening;
  opening.resampling = resampling_options(spacing, grid, radius_factor, variant, uniform_support, threads);
  opening.resampling.second_pass_where_sparse = !one_pass;
  opening.resampling.keep_rims = rims;
  check_dim(dim);
  opening.dimension = dim;
  if (!mesh.empty()) mesh_format_from_extension(mesh);
  PreparedShape prepared = prepare_shape(shape, opening);
  const std::string& path = prepared.path;
  Resampled out;
  run_released([&] {
    ThreadPool pool(threads);
    OpenedShape opened = open_input(prepared, opening, pool);
    out.warnings = opened.warnings;
    PointSetResampling options = opening.resampling;
    options.spacing = opened.spacing.h;
    options.grid = 0;
    if (opened.dimension == 2) {
      resample_opened<2>(opened, path, options, mesh, clock, out);
    } else {
      resample_opened<3>(opened, path, options, mesh, clock, out);
    }
  });
  warn_all(out.warnings);
  if (out.clear_loss) {
    if (!accept_loss)
      throw std::runtime_error(out.loss_message +
                               ". Holes open where h is well below the input's spacing (without spacing and grid, h "
                               "follows it) or where the input is sparser than the widened supports reach (a larger "
                               "radius_factor widens every support); accept_loss=True takes this output as a success");
    warn_all({out.loss_message + " (accepted: accept_loss=True)"});
  }
  const auto [positions, new_normals] = points_and_normals(out.points, out.dimension);
  if (with_rim) return py::make_tuple(positions, new_normals, rim_marks_of(out.points), to_python(out.report));
  return py::make_tuple(positions, new_normals, to_python(out.report));
}

template <int D>
void mesh_of(const OpenedShape& opened, const PointSetResampling& options, const std::string& out_path,
             ThreadPool& pool, SurfaceMesh<D>& mesh) {
  const PointSet<D> points = from_3d<D>(opened.points);
  const Grid<D> grid = resampling_grid(points, opened.spacing.h, options.radius_factor);
  mesh = extract_mesh(points, grid, AmlsParameters{options.radius_factor}, options.variant, pool).mesh;
  if (mesh.cells.empty())
    throw std::runtime_error(
        "no mesh: the surface crosses no grid edge near the points (F is undefined or of one "
        "sign there; are the points too sparse for h?)");
  if (!out_path.empty()) write_surface_mesh(out_path, mesh);
}

py::tuple mesh(py::object points, py::object normals, py::object spacing, py::object grid, double radius_factor,
               const std::string& variant, int threads, const std::string& out) {
  const ShapeArguments shape{std::move(points), std::move(normals), 0};
  ShapeOpening opening;
  opening.resampling = resampling_options(spacing, grid, radius_factor, variant, true, threads);
  if (!out.empty()) mesh_format_from_extension(out);
  PreparedShape prepared = prepare_shape(shape, opening);
  int dimension = 3;
  SurfaceMesh<2> mesh2;
  SurfaceMesh<3> mesh3;
  run_released([&] {
    ThreadPool pool(threads);
    const OpenedShape opened = open_input(prepared, opening, pool);
    dimension = opened.dimension;
    if (dimension == 2) {
      mesh_of<2>(opened, opening.resampling, out, pool, mesh2);
    } else {
      mesh_of<3>(opened, opening.resampling, out, pool, mesh3);
    }
  });
  if (dimension == 2) return py::make_tuple(to_array(mesh2.vertices), cells_to_array(mesh2.cells));
  return py::make_tuple(to_array(mesh3.vertices), cells_to_array(mesh3.cells));
}

}  // namespace

void bind_resample(py::module_& m) {
  m.def("resample", &resample, py::arg("points"), py::arg("normals") = py::none(), py::kw_only(),
        py::arg("spacing") = py::none(), py::arg("grid") = py::none(), py::arg("radius_factor") = 3.0,
        py::arg("variant") = "exact", py::arg("uniform_support") = false, py::arg("accept_loss") = false,
        py::arg("dim") = 0, py::arg("threads") = 1, py::arg("mesh") = "", py::arg("rim") = py::none(),
        py::arg("one_pass") = false, py::arg("with_rim") = false, py::arg("rims") = true,
        R"(resample(points, normals=None, *, spacing=None, grid=None, radius_factor=3.0, variant="exact",
         uniform_support=False, accept_loss=False, dim=0, threads=1, mesh="", rim=None, one_pass=False,
         with_rim=False, rims=True) -> (points, normals, report) or (points, normals, rim, report)

`amls resample`: resamples a surface on a grid (the unit square/cube, or the input's padded
bounding box when it lies outside) and returns the new points: once, or twice where the input is
sparser than h (one_pass). Input: a point set with normals (broken normals, against or across
those of the points beside them within Delta, are mended with a warning), one without (normals estimated by the Pratt fit and oriented over a neighbour graph), or a file path
(str or os.PathLike) of any format the command line reads - a point set, or a triangle mesh (.obj,
.stl, or .ply or .off with faces; sampled at h with face normals).

h: spacing, else grid, else from the input: the spacing the file records (amls writes it into its
output), else the step of the grid lines its points lie on, else the median distance from a point
(a mesh: a vertex) to its 4th nearest neighbour, halved. Refused up front when the output would pass
50 million points. Afterwards the coverage of the input by the output is measured; a clear loss
(under 99 % of the input covered, or under 95 % of the output on the input) raises RuntimeError
unless accept_loss.

  points           float64 array (n, 3) or (n, 2), or a file path
  normals          arrays: unit normals, the same shape, or None (estimated); a file path: None (the
                   file's own, broken ones mended) or "estimated" (the file's set aside and estimated,
                   as `--normals estimated`, for a file whose normals are unoriented)
  spacing          grid spacing h, in the input's units, within [1e-9, 1e9]
  grid             N cells within [1, 65536]: h = 1/N when the input lies within the unit
                   square/cube, else its bounding box's longest side / N
  radius_factor    the influence radius Delta in units of h, within [1.5, 32] (default 3)
  variant          "exact" (roots of F on the grid edges) or "interpolated"
  uniform_support  one support Delta for every point, as the paper's tests use, instead of widening
                   it where the input is sparse
  accept_loss      return even when the output clearly misses part of the input (with a warning)
  dim              a file read as 2D or 3D (default: from the file)
  threads          within [1, 256]; the result does not depend on it
  mesh             also write the new points' surface as a mesh (.obj, .ply, .stl; 2D: a polyline),
                   as `amls resample --mesh` does
  rim              arrays only: None, or one value per point, True (1) where the point is on an
                   open surface's rim (read(..., with_rim=True) or an earlier with_rim=True gives
                   them): marked rim points stay on the rim, as a .ply file's marks do for
                   `amls resample`; a file path brings its own marks, and rim= with one raises
  one_pass         resample once, as the paper does (`--one-pass`). By default an input sparser
                   than h at 1 % of its points or more (its supports widened there) gets a second
                   pass: the first pass's points resampled at h, which fills the small holes that
                   F of the sparse input leaves, so that resampling the output again changes little
  with_rim         also return the new points' rim marks, as `amls resample` writes them into a
                   .ply output
  rims             True (default): an open surface keeps its rims, as `--rims on`; False: the
                   paper's resampler, which extends an open surface's rim by up to a support
                   (`--rims off`; a closed surface is the same either way)

Returns the new points and their normals (float64, the input's dimension), with with_rim their rim
marks (bool (n,), True on an open surface's carried rim), and the report: a dict with the keys of
`amls resample --json` (h, points_in, points_out, passes, first_pass_points, spacing_h, coverage,
rim, seconds, peak_memory_mib, ...; "output" is "" as nothing is written).
Raises ValueError for arguments out of range or bad arrays (shape, NaN, complex, zero normals, rim
marks not one 0 or 1 per point, rim= with a file path), when no h can be chosen (too few distinct
points: give spacing or grid) and when h is past the cost limits (the message names the spacing
that would fit); OSError for a file that cannot be read or
written (FileNotFoundError, IsADirectoryError, PermissionError where the system says so); and
RuntimeError when the output misses part of the input (without accept_loss) or no point results.)");
  m.def("mesh", &mesh, py::arg("points"), py::arg("normals") = py::none(), py::kw_only(),
        py::arg("spacing") = py::none(), py::arg("grid") = py::none(), py::arg("radius_factor") = 3.0,
        py::arg("variant") = "exact", py::arg("threads") = 1, py::arg("out") = "",
        R"(mesh(points, normals=None, *, spacing=None, grid=None, radius_factor=3.0, variant="exact", threads=1,
     out="") -> (vertices, faces)

The surface S(P) of a point set as a triangle mesh (2D: a polyline), by marching simplices over the
grid cubes it crosses, as `amls resample --mesh` writes it (docs/mesh-export.md). h as resample()
chooses it (pass the h a resample reported to mesh its points on their own grid); `points` and
`normals` as resample() takes them (None with arrays, or "estimated", are estimated).

  out   also write the mesh (.obj, .ply, .stl)

Returns vertices, float64 (n, 3) or (n, 2), and faces, int64 (m, 3) (2D: segments, (m, 2)),
counter-clockwise seen from outside. Raises as resample() does, and RuntimeError when the surface
crosses no grid edge.)");
}

}  // namespace amls::python
