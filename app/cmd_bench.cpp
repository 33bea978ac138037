// amls bench: the fixed benchmark suite, one table.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "app/commands.hpp"
#include "app/common_options.hpp"
#include "app/flow_report.hpp"
#include "core/run/bench_suite.hpp"

namespace amls::app {

namespace {

struct BenchOptions {
  int threads = 1;
  std::string json_path;
  std::vector<std::string> only;
};

bool selected(const std::string& name, const std::vector<std::string>& only) {
  if (only.empty()) return true;
  for (const std::string& part : only)
    if (name.find(part) != std::string::npos) return true;
  return false;
}

nlohmann::json to_json(const BenchCase& c) {
  nlohmann::json timings = nlohmann::json::object();
  for (const PhaseTime& p : c.timings) timings[p.phase] = p.seconds;
  timings["total"] = total_seconds(c.timings);
  nlohmann::json figures = nlohmann::json::object();
  for (const auto& [name, value] : c.figures) figures[name] = value;
  return {{"name", c.name},
          {"figures", figures},
          {"points", c.points},
          {"points_processed", c.points_processed},
          {"points_per_second", c.points_per_second()},
          {"timings_s", timings},
          {"peak_memory_mib", c.peak_memory_mib},
          {"threads", c.threads},
          // The case's whole run: its wall time and the share of it outside
          // parallel loops (on one thread, the part more threads cannot share).
          {"wall_s", c.run.wall},
          {"parallel_s", c.run.parallel},
          {"serial_share", c.run.serial_share()},
          {"result", c.result}};
}

void print_row(const BenchCase& c) {
  const PhaseTimes& t = c.timings;
  std::printf("%-28s %8zu %8.3f %8.3f %8.3f %8.3f %8.3f %9.3f %11.3g %8.1f %6.3f  %s\n", c.name.c_str(), c.points,
              seconds_of(t, "normals"), seconds_of(t, "function"), seconds_of(t, "resample"), seconds_of(t, "deform"),
              seconds_of(t, "hash"), total_seconds(t), c.points_per_second(), c.peak_memory_mib, c.run.serial_share(),
              c.result.c_str());
  std::fflush(stdout);
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "the fixed benchmark suite: 2D vortex 512^2 exact and interpolated; one full step on 3D spheres of 50k, 200k "
      "and 1M points; a 40-step drag on 200k and 1M points, resampled always or locally; Enright 128^3. Prints seconds per phase, points per second, peak memory and the serial share (of the case's wall time, outside parallel loops) per case");
  add_threads_option(*cmd, options->threads);
  cmd->add_option("--json", options->json_path, R"(write {"cases": [...]} to this file)");
  cmd->add_option("--only", options->only,
                  "run only the cases whose name contains this text (repeatable), e.g. --only 50k --only vortex");
  cmd->callback([options] {
    std::vector<BenchSpec> specs;
    for (BenchSpec& spec : bench_suite(options->threads))
      if (selected(spec.name, options->only)) specs.push_back(std::move(spec));
    if (specs.empty()) {
      std::string names;
      for (const BenchSpec& spec : bench_suite(options->threads)) names += "\n  " + spec.name;
      throw CLI::ValidationError("--only", "no case matches; the cases are:" + names);
    }
    std::printf("amls bench, %d thread%s, %u hardware threads\n", options->threads, options->threads == 1 ? "" : "s",
                std::thread::hardware_concurrency());
    std::printf("%-28s %8s %8s %8s %8s %8s %8s %9s %11s %8s %6s  %s\n", "case", "points", "normals", "function",
                "resample", "deform", "hash", "total s", "points/s", "peak MiB", "serial", "result");
    // Rows are printed as each case finishes, so a long suite shows progress.
    nlohmann::json cases = nlohmann::json::array();
    for (const BenchSpec& spec : specs) {
      const BenchCase c = spec.run();
      print_row(c);
      cases.push_back(to_json(c));
    }
    if (!options->json_path.empty()) write_json_file(options->json_path, {{"cases", cases}});
  });
}

}  // namespace amls::app
