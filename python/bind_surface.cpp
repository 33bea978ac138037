// Surface and MlsDeformation: the paper's loop (core/run/deforming_surface)
// driven step by step from Python, as `amls deform` drives it from a scene.
#include <memory>
#include <mutex>
#include <optional>
#include <variant>

#include "core/deform/mls_deformation.hpp"
#include "core/io/mesh_writer.hpp"
#include "core/io/point_set_io.hpp"
#include "core/resample/mesh_extraction.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/util/parameter_ranges.hpp"
#include "python/bindings.hpp"
#include "python/released_work.hpp"
#include "python/shape_input.hpp"
#include "python/surface_projection.hpp"

namespace amls::python {

namespace {

// Handles at their current positions; a step moves them to its targets.
struct Handles {
  int dimension = 3;
  std::vector<Vec<3>> positions;  // a 2D handle has z = 0
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
};

template <int D>
std::vector<Vec<D>> handle_vectors(const py::handle& array, const char* name) {
  std::vector<Vec<D>> v = vectors_from<D>(array, name);
  check_range(std::string(name) + " count", static_cast<double>(v.size()), ranges::kHandles);
  return v;
}

Handles make_handles(const py::object& handles, const std::string& kind, double alpha) {
  Handles out;
  out.dimension = dimension_of(handles, "handles");
  if (out.dimension == 2) {
    for (const Vec<2>& v : handle_vectors<2>(handles, "handles")) out.positions.push_back({v.x(), v.y(), 0.0});
  } else {
    out.positions = handle_vectors<3>(handles, "handles");
  }
  out.kind = parse_mls_kind(kind);
  check_range("alpha", alpha, ranges::kAlpha);
  out.alpha = alpha;
  return out;
}

py::dict step_dict(const StepStats& s) {
  const PhaseTimings& t = s.timings;
  py::dict timings;
  timings["normals"] = t.normals;
  timings["function"] = t.function;
  timings["resample"] = t.resample;
  timings["deform"] = t.deform;
  timings["hash"] = t.hash;
  timings["total"] = t.total();
  py::dict d;
  d["points_before"] = s.points_before;
  d["points_after"] = s.points_after;
  d["inserted"] = s.resample.inserted;
  d["failed_normal_fits"] = s.normals.failed();
  d["timings_s"] = timings;
  return d;
}

template <int D>
class SurfaceOf {
 public:
  static constexpr int dimension = D;

  SurfaceOf(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant, int threads, PointSet<D> points)
      : loop_(grid, parameters, variant, threads) {
    loop_.set_points(std::move(points));
  }

  DeformingSurface<D>& loop() { return loop_; }

  // The surface ready to evaluate: pseudo-normals of the current points.
  const AmlsSurface<D>& evaluable() {
    if (!evaluable_) {
      loop_.refresh_normals();
      evaluable_ = true;
    }
    return loop_.surface();
  }

  StepStats resample() {
    const StepStats s = resample_next();
    evaluable_ = true;
    return s;
  }

  // As a scene's step under `always` (core/run/settle.hpp, scene_run.cpp): the resample on its own,
  // then the deformation alone - which leaves the points in the scene's order, bit for bit.
  StepStats step(const Handles& from, const std::vector<Vec<3>>& to, bool resample) {
    const MlsDeformation<D> deformation(from_3d<D>(from.positions), from_3d<D>(to), from.kind, from.alpha);
    evaluable_ = false;
    if (!resample) return loop_.step(deformation, 0.0, 1.0, false);
    StepStats s = resample_next();
    const StepStats deformed = loop_.step(deformation, 0.0, 1.0, false);
    s.timings += deformed.timings;
    s.points_after = deformed.points_after;
    return s;
  }

 private:
  // The first resample of the shape's own samples is a scene's start
  // (DeformingSurface::resample_start: a second pass where they are sparser
  // than h), so that a loop here stays a scene's bit for bit; later ones are one pass.
  StepStats resample_next() {
    const bool start = !resampled_;
    resampled_ = true;
    return start ? loop_.resample_start() : loop_.resample_only();
  }

  DeformingSurface<D> loop_;
  bool evaluable_ = false;
  bool resampled_ = false;
};

class Surface {
 private:
  template <typename Fn>
  auto visit(Fn&& fn) {
    if (surface_.index() == 1) return fn(*std::get<1>(surface_));
    return fn(*std::get<2>(surface_));
  }
  // One call at a time: the loop is not made for concurrent use.
  void run_locked(const std::function<void()>& work) {
    run_released([&] {
      std::lock_guard lock(mutex_);
      work();
    });
  }

 public:
  Surface(py::object points, py::object normals, py::object h, py::object grid, double radius_factor,
          const std::string& variant, bool uniform_support, int threads) {
    const ShapeArguments shape{std::move(points), std::move(normals), 0};
    ShapeOpening opening;
    opening.resampling = resampling_options(h, grid, radius_factor, variant, uniform_support, threads);
    PreparedShape prepared = prepare_shape(shape, opening);
    std::vector<std::string> warnings;
    run_released([&] {
      ThreadPool pool(threads);
      OpenedShape opened = open_input(prepared, opening, pool);
      warnings = opened.warnings;
      h_ = opened.spacing.h;
      AmlsParameters parameters{radius_factor};
      parameters.widen_support = opening.resampling.widen_support;
      if (opened.dimension == 2) {
        PointSet<2> p = to_2d(opened.points);
        const Grid<2> g = resampling_grid(p, h_, radius_factor);
        surface_.emplace<1>(
            std::make_unique<SurfaceOf<2>>(g, parameters, opening.resampling.variant, threads, std::move(p)));
      } else {
        const Grid<3> g = resampling_grid(opened.points, h_, radius_factor);
        surface_.emplace<2>(std::make_unique<SurfaceOf<3>>(g, parameters, opening.resampling.variant, threads,
                                                           std::move(opened.points)));
      }
    });
    warn_all(warnings);
  }

  int dimension() const { return surface_.index() == 1 ? 2 : 3; }
  double h() const { return h_; }

  py::object points() {
    return visit([](auto& s) { return py::object(to_array(s.loop().points().positions)); });
  }
  py::object normals() {
    return visit([](auto& s) { return py::object(to_array(s.loop().points().normals)); });
  }
  py::object rim() {
    return visit([](auto& s) { return py::object(rim_marks_of(s.loop().points())); });
  }

  py::object F(const py::object& x) {
    return visit([&](auto& s) {
      constexpr int D = std::remove_reference_t<decltype(s)>::dimension;
      bool single = false;
      const std::vector<Vec<D>> positions = positions_from<D>(x, "x", single);
      std::vector<double> values;
      run_locked([&] { values = evaluate_all(s.evaluable(), positions, s.loop().pool()); });
      return single ? py::object(py::float_(values[0])) : py::object(to_array(values));
    });
  }

  py::object project(const py::object& x) {
    return visit([&](auto& s) {
      constexpr int D = std::remove_reference_t<decltype(s)>::dimension;
      bool single = false;
      std::vector<Vec<D>> positions = positions_from<D>(x, "x", single);
      run_locked([&] { project_onto(s.evaluable(), positions, s.loop().pool()); });
      py::object out = to_array(positions);
      return single ? py::object(out[py::int_(0)]) : out;
    });
  }

  py::dict resample() {
    StepStats stats;
    visit([&](auto& s) { run_locked([&] { stats = s.resample(); }); });
    return step_dict(stats);
  }

  py::dict step(Handles& deformation, const py::object& targets, bool resample) {
    if (deformation.dimension != dimension())
      throw std::invalid_argument("deformation: " + std::to_string(deformation.dimension) + "D handles for a " +
                                  std::to_string(dimension()) + "D surface");
    const Handles to = make_handles(targets, to_string(deformation.kind), deformation.alpha);
    if (to.positions.size() != deformation.positions.size())
      throw std::invalid_argument("targets: " + std::to_string(to.positions.size()) + " rows for " +
                                  std::to_string(deformation.positions.size()) + " handles");
    StepStats stats;
    visit([&](auto& s) { run_locked([&] { stats = s.step(deformation, to.positions, resample); }); });
    deformation.positions = to.positions;
    return step_dict(stats);
  }

  py::tuple mesh(const std::string& out) {
    if (!out.empty()) mesh_format_from_extension(out);
    return visit([&](auto& s) {
      constexpr int D = std::remove_reference_t<decltype(s)>::dimension;
      SurfaceMesh<D> mesh;
      run_released([&] {
        std::lock_guard lock(mutex_);
        mesh = extract_mesh(s.evaluable(), s.loop().variant(), s.loop().pool()).mesh;
        if (mesh.cells.empty()) throw std::runtime_error("no mesh: the surface crosses no grid edge near the points");
        if (!out.empty()) write_surface_mesh(out, mesh);
      });
      return py::make_tuple(to_array(mesh.vertices), cells_to_array(mesh.cells));
    });
  }

 private:
  std::variant<std::monostate, std::unique_ptr<SurfaceOf<2>>, std::unique_ptr<SurfaceOf<3>>> surface_;
  double h_ = 0.0;
  std::mutex mutex_;
};

}  // namespace

void bind_surface(py::module_& m) {
  py::class_<Handles>(m, "MlsDeformation", R"(MlsDeformation(handles, kind="rigid", alpha=1.0)

Handle-driven moving-least-squares deformation (Schaefer et al. 2006; in 3D, Zhu & Gortler 2007), as
a scene's stages use it: Surface.step(deformation, targets) maps every point by the map that best
takes the handles from where they are to `targets`, then leaves the handles at the targets, so a
loop of steps drags them along a path.

  handles  float64 (k, 3) or (k, 2), 1 to 1024 handles
  kind     "rigid" (default), "similarity" or "affine"
  alpha    the weights' exponent, w_i = 1 / |p_i - v|^(2 alpha), within [0.1, 10])")
      .def(py::init(&make_handles), py::arg("handles"), py::arg("kind") = "rigid", py::arg("alpha") = 1.0)
      .def_property_readonly(
          "handles",
          [](const Handles& h) {
            return h.dimension == 2 ? py::object(to_array(from_3d<2>(h.positions))) : py::object(to_array(h.positions));
          },
          "the handles' current positions")
      .def_property_readonly("kind", [](const Handles& h) { return std::string(to_string(h.kind)); })
      .def_property_readonly("alpha", [](const Handles& h) { return h.alpha; })
      .def("__repr__", [](const Handles& h) {
        return "MlsDeformation(" + std::to_string(h.positions.size()) + " handles, kind=\"" + to_string(h.kind) + "\")";
      });

  py::class_<Surface>(m, "Surface", R"(Surface(points, normals=None, *, h=None, grid=None, radius_factor=3.0,
        variant="exact", uniform_support=False, threads=1)

The AMLS surface S(P) of oriented points (paper, section 2), on a grid of spacing h, to evaluate,
resample and deform step by step - the loop `amls deform` runs for a scene (Update_Normals,
Update_Function, Resample, Deform, Hash). The points are opened as resample() opens them: `points`
and `normals` as resample() takes them (an array, a file path; None or "estimated"), h (or grid)
as resample()'s spacing (grid).
The grid is the one `amls resample` would use for these points.)")
      .def(py::init<py::object, py::object, py::object, py::object, double, const std::string&, bool, int>(),
           py::arg("points"), py::arg("normals") = py::none(), py::kw_only(), py::arg("h") = py::none(),
           py::arg("grid") = py::none(), py::arg("radius_factor") = 3.0, py::arg("variant") = "exact",
           py::arg("uniform_support") = false, py::arg("threads") = 1)
      .def_property_readonly("points", &Surface::points, "the current points, float64 (n, D) (a copy)")
      .def_property_readonly("rim", &Surface::rim,
                             "bool (n,): True where a resample carried the point as the rim of an open surface "
                             "(write(..., rim=surface.rim) keeps the marks in a .ply file)")
      .def_property_readonly("normals", &Surface::normals, "the current points' unit normals, float64 (n, D)")
      .def_property_readonly("h", &Surface::h, "the grid spacing h")
      .def_property_readonly("dimension", &Surface::dimension, "2 or 3")
      .def("F", &Surface::F, py::arg("x"), R"(F(x) -> float or array

The implicit function F of S(P) (zero on the surface, positive outside) at one position (D,) or
many (m, D); NaN where F is undefined (no point's support reaches x).)")
      .def("project", &Surface::project, py::arg("x"), R"(project(x) -> array

Positions (D,) or (m, D) moved onto S(P) by Newton's steps along F's fitted gradient; NaN where F is
undefined.)")
      .def("resample", &Surface::resample, R"(resample() -> dict

Resamples S(P) in place on the grid (no deformation). The first resample of the shape's own
samples (here or in step) is a scene's start: where they are sparser than h (supports widened at
1 % of them or more) it makes a second pass, as `amls resample` and `amls deform` do. Returns the
step's counts and timings (points_before, points_after, inserted, failed_normal_fits, timings_s).)")
      .def("step", &Surface::step, py::arg("deformation"), py::arg("targets"), py::arg("resample") = true,
           R"(step(deformation, targets, resample=True) -> dict

One step of the paper's loop: resample S(P) (unless resample=False), then deform the points by the
MLS map taking the deformation's handles to `targets` (the same shape as its handles), and hash
them. The handles are left at the targets. A scene's step under `--resample always` is this step;
after the last one, resample() gives the scene's final frame.)")
      .def("mesh", &Surface::mesh, py::arg("out") = "", R"(mesh(out="") -> (vertices, faces)

The current surface as a triangle mesh (2D: a polyline), as mesh() makes it; `out` also writes it
(.obj, .ply, .stl).)");
}

}  // namespace amls::python
