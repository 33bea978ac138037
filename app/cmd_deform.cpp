// amls deform: runs a scene - its shape deformed through its handle stages -
// writing frames and a report.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/deform_report.hpp"
#include "app/flow_report.hpp"
#include "app/terminal_progress.hpp"
#include "core/io/mesh_writer.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/scene_report_json.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/staged_directory.hpp"

namespace amls::app {

namespace {

// Written last into a complete output directory.
constexpr const char* kReportName = "report.json";

struct DeformOptions {
  std::string scene;
  std::string out_dir;
  std::size_t frames_every = 1;
  std::string format = "ply";
  std::string resample = "always";
  bool no_resample = false;
  int threads = 1;
  double tracers_per_point = 50.0;
  std::size_t max_steps = 0;
  std::string json_path;
  std::string mesh_path;
  bool keep_rims = AmlsParameters{}.keep_rims;
};

std::string frame_name(std::size_t step, std::size_t steps, const std::string& format) {
  const int width = std::max(5, static_cast<int>(std::to_string(steps).size()));
  char name[64];
  std::snprintf(name, sizeof name, "frame_%0*zu.%s", width, step, format.c_str());
  return name;
}

template <int D>
void run(const Scene<D>& scene, const DeformOptions& options, const ResamplePolicy& policy) {
  SceneRunOptions run_options;
  run_options.resample = !options.no_resample;
  run_options.policy = policy;
  run_options.threads = options.threads;
  run_options.tracers_per_point = options.tracers_per_point;
  run_options.max_steps = options.max_steps;
  const std::size_t steps = options.max_steps > 0 ? std::min(options.max_steps, scene.history.total_steps())
                                                  : scene.history.total_steps();
  const PointFileFormat format = options.format == "xyz" ? PointFileFormat::xyz : PointFileFormat::ply_binary_little_endian;
  std::optional<StagedDirectory> out;
  if (!options.out_dir.empty()) out.emplace(options.out_dir, kReportName);
  std::optional<PointSet<D>> last_frame;  // for --mesh
  FrameSink<D> frames;
  // Resampled frames record the run's h, so that opening one chooses it again.
  const double frame_spacing = run_options.resample ? scene.h() : 0.0;
  if (out || !options.mesh_path.empty())
    frames = [&](std::size_t step, const PointSet<D>& points) {
      if (out && (step % options.frames_every == 0 || step == steps))
        write_point_set(out->file(frame_name(step, steps, options.format)), points, format, frame_spacing);
      if (!options.mesh_path.empty() && step == steps) last_frame = points;
    };
  FrameSink<D> exact;
  if (out)
    exact = [&](std::size_t, const PointSet<D>& tracers) {
      write_point_set(out->file("exact." + options.format), tracers, format);
    };
  TerminalProgress progress;
  const SceneRunReport report = [&] {
    try {
      return run_scene<D>(
          scene, run_options, frames,
          [&](std::size_t k, std::size_t n, std::size_t p) { progress.update(k, n, static_cast<double>(k), p); }, exact);
    } catch (...) {
      // Stopped on Ctrl+C: the frames so far are no output (a run that failed
      // keeps them in DIR.partial, for a look at what went wrong).
      if (out && interrupt_requested()) std::filesystem::remove_all(out->staging_path());
      throw;
    }
  }();
  for (const std::string& warning : report.warnings) std::cerr << "amls: warning: " << warning << "\n";
  print_summary(std::cout, report);
  if (last_frame) {
    const Grid<D> grid(report.grid_origin.template head<D>(), report.h);
    std::cout << "mesh of step " << steps << ": "
              << export_surface_mesh(options.mesh_path, *last_frame, grid, scene.parameters(),
                                     scene.variant, options.threads)
                     .summary()
              << ", wrote " << options.mesh_path << "\n";
  } else if (!options.mesh_path.empty()) {
    std::cerr << "amls: warning: no mesh written: the run stopped before step " << steps << "\n";
  }
  const nlohmann::json json = scene_report_json(report);
  if (!options.json_path.empty()) write_json_file(options.json_path, json);
  if (out) {
    write_json_file(out->file(kReportName), json);
    out->commit();
    std::cout << "frames: " << out->path() << "\n";
  }
}

}  // namespace

void add_deform_command(CLI::App& app) {
  auto options = std::make_shared<DeformOptions>();
  CLI::App* cmd = app.add_subcommand(
      "deform",
      "run a scene (docs/scene-format.md): deform its shape through its handle stages with MLS deformation, "
      "resampling after every step (or as --resample says), and report the sampling quality and the distance to "
      "the exact deformed shape");
  cmd->add_option("scene", options->scene, "scene file (.json)")->required();
  cmd->add_option("--out-dir", options->out_dir,
                  "write frames (frame_00000.ply, ...), the exact deformed shape's tracers (exact.ply) and report.json here; they go to DIR.partial first, which is "
                  "renamed to DIR only when the run completes");
  cmd->add_option("--frames-every", options->frames_every, "write every K-th frame (the last is always written)")
      ->check(in_range(ranges::kFramesEvery))
      ->capture_default_str();
  cmd->add_option("--format", options->format, "frame format: ply (binary) or xyz")
      ->check(CLI::IsMember({"ply", "xyz"}))
      ->capture_default_str();
  CLI::Option* resample = add_resample_option(*cmd, options->resample);
  cmd->add_flag("--no-resample", options->no_resample,
                "deform the initial points without resampling (the point set thins out and the surface breaks; the "
                "report says at which step)")
      ->excludes(resample);
  add_threads_option(*cmd, options->threads);
  cmd->add_option("--tracers", options->tracers_per_point,
                  "tracer points per initial point, standing for the exact deformed shape")
      ->check(in_range(ranges::kTracersPerPoint))
      ->capture_default_str();
  cmd->add_option("--max-steps", options->max_steps, "stop after this many steps (0: all)")->capture_default_str();
  cmd->add_option("--json", options->json_path, "also write the JSON report to this file");
  cmd->add_option("--mesh", options->mesh_path, "write the last frame's surface as a mesh (.obj, .ply, .stl; 2D: a polyline, .obj or .ply)");
  add_rims_option(*cmd, options->keep_rims);
  cmd->callback([options] {
    const ResamplePolicy policy = ResamplePolicy::parse(options->resample);
    if (!options->mesh_path.empty()) mesh_format_from_extension(options->mesh_path);
    AnyScene scene = read_scene(options->scene);
    std::visit([&](auto& s) { s.keep_rims = options->keep_rims; }, scene);
    if (const Scene<2>* s2 = std::get_if<Scene<2>>(&scene)) {
      run<2>(*s2, *options, policy);
    } else {
      run<3>(std::get<Scene<3>>(scene), *options, policy);
    }
  });
}

}  // namespace amls::app
