// amls vortex / amls enright: the paper's accuracy tests.
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/flow_report.hpp"
#include "app/terminal_progress.hpp"
#include "core/run/flow_test.hpp"
#include "core/io/point_set_io.hpp"

namespace amls::app {

namespace {

struct FlowTestOptions {
  FlowTestConfig config;
  std::string variant = "exact";
  std::string resample = "always";
  std::string json_path;
  std::string out_path;
};

template <int D>
using Runner = FlowTestRun<D> (*)(const FlowTestConfig&, const FlowProgress&);

template <int D>
void add_flow_test_command(CLI::App& app, const std::string& name, const std::string& description, int default_grid,
                           Runner<D> runner) {
  auto options = std::make_shared<FlowTestOptions>();
  options->config.grid = default_grid;
  CLI::App* cmd = app.add_subcommand(name, description);
  cmd->add_option("--grid", options->config.grid, "cells per unit length: h = 1/N")
      ->check(in_range(ranges::kFlowTestGridCells))
      ->capture_default_str();
  add_variant_option(*cmd, options->variant, true);
  add_flow_test_options(*cmd, options->config);
  add_threads_option(*cmd, options->config.threads);
  add_resample_option(*cmd, options->resample);
  cmd->add_option("--json", options->json_path, "write the JSON report to this file");
  cmd->add_option("--out", options->out_path, "write the final point set to this file (.ply or .xyz)");
  cmd->callback([options, runner] {
    options->config.variant = parse_flow_variant(options->variant);
    options->config.resample = ResamplePolicy::parse(options->resample);
    // Check the output's extension before the run, not after it.
    const PointFileFormat format = options->out_path.empty() ? PointFileFormat::xyz
                                                             : format_from_extension(options->out_path);
    TerminalProgress progress;
    const FlowTestRun<D> run = runner(options->config, [&](std::size_t k, std::size_t n, double t, std::size_t p) {
      progress.update(k, n, t, p);
    });
    print_table(std::cout, run.report);
    if (!options->json_path.empty()) write_json_file(options->json_path, to_json(run.report));
    if (!options->out_path.empty()) write_point_set(options->out_path, run.final_points, format);
  });
}

}  // namespace

void add_flow_test_commands(CLI::App& app) {
  add_flow_test_command<2>(app, "vortex",
                        "single-vortex test (2D): a circle r = 0.15 at (0.5, 0.75) deformed from t = 0 to 8 and "
                        "back, resampled every dt; prints time per phase and the L1 error",
                        256, &run_vortex_test);
  add_flow_test_command<3>(app, "enright",
                        "Enright test (3D): a sphere r = 0.15 at (0.35, 0.35, 0.35) deformed from t = 0 to 3 and "
                        "back, resampled every dt; prints time per phase and the volume loss",
                        128, &run_enright_test);
}

}  // namespace amls::app
