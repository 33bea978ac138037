// run_scene: `amls deform` (core/run/scene_run) on a scene file.
#include "core/io/point_set_io.hpp"
#include "core/run/scene_report_json.hpp"
#include "core/util/parameter_ranges.hpp"
#include "python/array_conversion.hpp"
#include "python/bindings.hpp"
#include "python/released_work.hpp"

namespace amls::python {

namespace {

struct SceneResult {
  int dimension = 3;
  PointSet<3> points;  // the last frame
  std::string report;  // JSON text
  std::vector<std::string> warnings;
};

template <int D>
void run(const Scene<D>& scene, const SceneRunOptions& options, SceneResult& out) {
  const FrameSink<D> last = [&](std::size_t, const PointSet<D>& points) { out.points = held_in_3d(points); };
  const SceneRunReport report = run_scene<D>(scene, options, last);
  out.dimension = D;
  out.report = scene_report_json(report).dump();
  out.warnings = report.warnings;
}

py::tuple run_scene_file(const std::string& path, const std::string& resample, int threads, double tracers,
                         std::size_t max_steps) {
  SceneRunOptions options;
  options.resample = resample != "off";
  if (options.resample) options.policy = ResamplePolicy::parse(resample);
  check_range("threads", threads, ranges::kThreads);
  check_range("tracers", tracers, ranges::kTracersPerPoint);
  options.threads = threads;
  options.tracers_per_point = tracers;
  options.max_steps = max_steps;
  SceneResult out;
  run_released([&] {
    const AnyScene scene = [&] {
      try {
        return read_scene(path);
      } catch (const FileError&) {
        throw;  // the scene or its shape file missing, a directory, unreadable: an OSError
      } catch (const std::runtime_error& e) {
        // Not the file but its contents: a key, a value out of range, bad JSON.
        throw std::invalid_argument(e.what());
      }
    }();
    if (const Scene<2>* s2 = std::get_if<Scene<2>>(&scene)) {
      run<2>(*s2, options, out);
    } else {
      run<3>(std::get<Scene<3>>(scene), options, out);
    }
  });
  warn_all(out.warnings);
  const auto [positions, normals] = points_and_normals(out.points, out.dimension);
  return py::make_tuple(positions, normals, to_python(out.report));
}

}  // namespace

void bind_scene(py::module_& m) {
  m.def("run_scene", &run_scene_file, py::arg("path"), py::kw_only(), py::arg("resample") = "always",
        py::arg("threads") = 1, py::arg("tracers") = 50.0, py::arg("max_steps") = 0,
        R"(run_scene(path, *, resample="always", threads=1, tracers=50.0, max_steps=0) -> (points, normals, report)

`amls deform`: runs a scene (docs/scene-format.md) - its shape deformed through its handle stages
with MLS deformation, resampling after every step (or as `resample` says) - and measures the
sampling quality and the distance to the exact deformed shape.

  resample   "always" (default), "auto", "every:K", "local", or "off" (deform the initial points
             without resampling: the point set thins out and the surface breaks)
  threads    within [1, 256]; the result does not depend on it
  tracers    tracer points per initial point, standing for the exact deformed shape, within [1, 1000]
  max_steps  stop after this many steps (0: all)

Returns the last frame's points and normals and the report: a dict with the keys of
`amls deform --json`. Raises FileNotFoundError for a missing scene or shape file it names,
IsADirectoryError for a directory in their place (both OSError), ValueError for a scene whose contents are wrong (the message names the
key) and for arguments out of range.)");
}

}  // namespace amls::python
