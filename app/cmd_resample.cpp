// amls resample: one resampling of a point set with oriented normals.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/flow_report.hpp"
#include "core/geometry/sample_spacing.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/mesh_writer.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/resampling_report.hpp"
#include "core/run/shape_opening.hpp"
#include "core/util/process_memory.hpp"
#include "core/util/stopwatch.hpp"

namespace amls::app {

namespace {

struct ResampleOptions {
  PointSetResampling resampling;
  std::string input;
  std::string output;
  std::string mesh;
  std::string json_path;
  std::string variant = "exact";
  int dimension = 0;
  bool accept_loss = false;
  bool uniform_support = false;
  bool one_pass = false;
  std::string normals = "given";
};

template <int D>
void resample_and_write(const PointSet<D>& input, std::size_t file_points, const TriangleMesh* closed_input,
                        const ResampleOptions& options, PointFileFormat format, Stopwatch& clock) {
  const ResampledPointSet<D> result = resample_point_set(input, options.resampling);
  require_resampled_points(result, options.resampling);
  // The spacing goes into the file, so that reading it back chooses this h again.
  write_point_set(options.output, result.points, format, result.grid.spacing());
  const double seconds = clock.lap();
  const double memory = peak_memory_mib();
  std::cout << "resample (" << D << "D, " << to_string(options.resampling.variant) << "): " << input.size()
            << " points in -> " << result.points.size() << " points out, h = " << result.grid.spacing()
            << ", nearest-neighbour spacing min/median/max = " << result.spacing_h.min << " / "
            << result.spacing_h.median << " / " << result.spacing_h.max << " h, wrote " << options.output << "\n";
  if (options.resampling.widen_support)
    std::cout << "support: Delta = " << options.resampling.radius_factor << " h, widened at "
              << result.widening.widened_points << " of " << input.size()
              << " points where the input is sparse (up to " << result.widening.widest << " Delta)\n";
  if (result.stats.first_pass_points > 0)
    std::cout << "second pass: the first pass's " << result.stats.first_pass_points
              << " points resampled once more at h, since the input is sparser than h at "
              << result.widening.widened_points << " points (--one-pass: one)\n";
  if (!options.mesh.empty())
    std::cout << "mesh: "
              << export_resampled_mesh(options.mesh, result, options.resampling, closed_input).summary()
              << ", wrote " << options.mesh << "\n";
  const RimReport& rim = result.rim;
  if (rim.samples_in + rim.samples_out > 0)
    std::cout << "rim: " << rim.samples_in << " rim samples in, " << rim.samples_out
              << " out; the output reaches " << rim.advance_h << " h past the input's rim\n";
  const Coverage& c = result.coverage;
  std::cout << "coverage: " << c.summary() << "\n";
  std::cout << "time " << seconds << " s, peak memory " << memory << " MiB\n";
  if (!options.json_path.empty()) {
    ResamplingRun run;
    run.input = options.input;
    run.output = options.output;
    run.file_points = file_points;
    run.points_in = input.size();
    run.seconds = seconds;
    run.peak_memory_mib = memory;
    const nlohmann::json j = resampling_report_json(result, options.resampling, run);
    write_json_file(options.json_path, j);
  }
  if (c.clear_loss()) {
    const std::string message = options.input + ": " + c.loss_message();
    if (!options.accept_loss)
      throw std::runtime_error(message + ". " + options.output +
                               " was written for inspection. Holes open where h is well below the input's spacing "
                               "(without --spacing and --grid, h follows it) or where the input is sparser than the widened "
                               "supports reach (a larger --radius-factor widens every support); --accept-loss takes this output as a success");
    std::cerr << "amls: warning: " << message << " (accepted: --accept-loss)\n";
  }
}

}  // namespace

void add_resample_command(CLI::App& app) {
  auto options = std::make_shared<ResampleOptions>();
  CLI::App* cmd = app.add_subcommand(
      "resample",
      "resample a surface on a grid (unit square/cube, or the input's padded bounding box when it lies "
      "outside) and write the new points: once, or twice where the input is sparser than h (--one-pass). "
      "Input: a point set with normals (.ply, .off, .xyz, .pwn, .csv, .txt; 2D or 3D; broken normals, against or "
      "across those of the points beside them within Delta, are mended with a warning), one without (normals estimated by the Pratt fit and oriented over a neighbour graph), or a triangle "
      "mesh (.obj, .stl, or .ply or .off with faces; sampled at h with face normals).\n"
      "h: --spacing, else --grid, else from the input: the spacing the file records (amls writes it into its "
      "output), else the step of the grid lines its points lie on (amls's output), else the median distance from a "
      "point (a mesh: a vertex) to its 4th nearest neighbour, halved, and for a mesh at most its longest side / 32 "
      "and, for a closed one of large flat faces, at most its mean thickness 3V/A / 16; for a point set whose points "
      "scatter across the surface by more than they lie apart (a noisy raw scan), at least 4 times that scatter, so "
      "that h resolves the surface, not the noise (docs/real-data.md). Refused up front when the output would pass "
      "50 million points. Afterwards the coverage of the input by the output is measured; a clear loss (under 99 % "
      "of the input covered, or under 95 % of the output on the input) fails the command unless --accept-loss");
  cmd->add_option("input", options->input, "point set or mesh to read (.ply, .off, .xyz, .pwn, .csv, .txt, .obj)")
      ->required();
  cmd->add_option("--out", options->output, "file to write (.ply: binary little endian, .xyz)")->required();
  cmd->add_option("--mesh", options->mesh, "also write the new points' surface as a mesh (.obj, .ply, .stl; 2D: a polyline, .obj or .ply)");
  CLI::Option* grid =
      cmd->add_option("--grid", options->resampling.grid,
                      "N cells: h = 1/N when the input lies within the unit square/cube, else its bounding box's "
                      "longest side / N")
          ->check(in_range(ranges::kGridCells));
  cmd->add_option("--spacing", options->resampling.spacing, "grid spacing h, in the input's units")
      ->check(in_range(ranges::kSpacing))
      ->excludes(grid);
  cmd->add_option("--dim", options->dimension, "read the input as 2D or 3D (default: from the file)")
      ->check(CLI::IsMember({2, 3}));
  cmd->add_option("--json", options->json_path,
                  "also write a report: h, point counts, spacing, coverage, time and peak memory");
  cmd->add_flag(
      "--uniform-support", options->uniform_support,
      "one support Delta for every point, as the paper's tests use, instead of widening it where the input is "
      "sparse (docs/real-data.md, \"Uneven density\")");
  cmd->add_flag("--one-pass", options->one_pass,
                "resample once, as the paper does. By default an input sparser than h at 1 % of its points or "
                "more (its supports widened there) gets a second pass: the first pass's points resampled at h, "
                "which fills the small holes that F of the sparse input leaves, so that resampling the output "
                "again changes little (docs/design.md, \"A second pass where the input is sparse\")");
  cmd->add_flag("--accept-loss", options->accept_loss,
                "exit 0 even when the output clearly misses part of the input (a warning is still printed)");
  cmd->add_option("--normals", options->normals,
                  "given: a point set's own normals, broken ones (against or across those of the points beside "
                  "them) mended with a warning; estimated: the file's normals set aside, and normals estimated and "
                  "oriented as for a set without, for a file whose normals are unoriented (a face's all pointing "
                  "inward). A mesh's samples take its faces' normals either way")
      ->check(CLI::IsMember({"given", "estimated"}))
      ->capture_default_str();
  add_radius_factor_option(*cmd, options->resampling.radius_factor);
  add_rims_option(*cmd, options->resampling.keep_rims);
  add_variant_option(*cmd, options->variant);
  add_threads_option(*cmd, options->resampling.threads);
  cmd->callback([options] {
    Stopwatch clock;
    options->resampling.variant = parse_variant(options->variant);
    options->resampling.widen_support = !options->uniform_support;
    options->resampling.second_pass_where_sparse = !options->one_pass;
    // Check the output's extension before any work is done.
    const PointFileFormat format = format_from_extension(options->output);
    if (!options->mesh.empty()) mesh_format_from_extension(options->mesh);
    // The road the editor takes too: read, choose h, sample (meshes at h, missing normals over Delta,
    // broken ones mended over Delta).
    ShapeOpening opening;
    opening.resampling = options->resampling;
    opening.dimension = options->dimension;
    opening.estimate_normals = options->normals == "estimated";
    ThreadPool pool(options->resampling.threads);
    OpenedShape shape = open_shape_file(options->input, opening, pool);
    std::cout << "h = " << shape.spacing.h << " (" << shape.spacing.reason << ")\n";
    options->resampling.spacing = shape.spacing.h;
    options->resampling.grid = 0;
    for (const std::string& warning : shape.warnings) std::cerr << "amls: warning: " << warning << "\n";
    std::cout << options->input << ": " << shape.source << "\n";
    if (shape.dimension == 2) {
      resample_and_write(to_2d(shape.points), shape.file_points, nullptr, *options, format, clock);
    } else {
      resample_and_write(shape.points, shape.file_points, shape.closed_mesh ? &*shape.closed_mesh : nullptr, *options,
                         format, clock);
    }
  });
}

}  // namespace amls::app
