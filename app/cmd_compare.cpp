// amls compare: the grid walk (exact, interpolated) against the ray-tracing
// baseline on one flow test, in one run: the paper's Tables 1 and 2 side by side.
#include <fstream>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/flow_report.hpp"
#include "app/terminal_progress.hpp"
#include "core/run/flow_test.hpp"

namespace amls::app {

namespace {

struct CompareOptions {
  FlowTestConfig config;
  std::string test = "vortex";
  int grid = 0;  // 0: the test's default
  std::string json_path;
};

// The 1-minute load average, or -1 where /proc/loadavg is missing: timings on
// a shared machine mean little without it.
double load_average() {
  std::ifstream file("/proc/loadavg");
  double load = -1.0;
  return file >> load ? load : -1.0;
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "run a flow test with the grid walk (exact, interpolated) and the ray-tracing baseline (Gois et al. 2008) "
      "and print time per phase, total against the ray tracer's, error and point counts side by side (the "
      "paper's Tables 1 and 2)");
  cmd->add_option("--test", options->test, "vortex (2D) or enright (3D)")
      ->check(CLI::IsMember({"vortex", "enright"}))
      ->capture_default_str();
  cmd->add_option("--grid", options->grid, "cells per unit length: h = 1/N (default: 256 vortex, 128 enright)")
      ->check(in_range(ranges::kFlowTestGridCells));
  add_flow_test_options(*cmd, options->config);
  add_threads_option(*cmd, options->config.threads);
  cmd->add_option("--json", options->json_path, "write {\"runs\": [report, report, report]} to this file");
  cmd->callback([options] {
    FlowTestConfig config = options->config;
    const bool vortex = options->test == "vortex";
    config.grid = options->grid > 0 ? options->grid : (vortex ? 256 : 128);
    const double load_before = load_average();
    std::vector<FlowTestReport> runs;
    for (const FlowVariant variant : {FlowVariant::exact, FlowVariant::interpolated, FlowVariant::raytrace}) {
      config.variant = variant;
      TerminalProgress progress;
      const FlowProgress report_progress = [&](std::size_t k, std::size_t n, double t, std::size_t p) {
        progress.update(k, n, t, p);
      };
      runs.push_back(vortex ? run_vortex_test(config, report_progress).report
                            : run_enright_test(config, report_progress).report);
    }
    print_comparison(std::cout, runs);
    const double load_after = load_average();
    if (load_before >= 0.0) std::cout << "load average (1 min): " << load_before << " before, " << load_after << " after\n";
    if (!options->json_path.empty()) {
      nlohmann::json json;
      json["runs"] = nlohmann::json::array();
      for (const FlowTestReport& r : runs) json["runs"].push_back(to_json(r));
      write_json_file(options->json_path, json);
    }
  });
}

}  // namespace amls::app
