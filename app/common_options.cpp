#include "app/common_options.hpp"

#include <cstdlib>
#include <vector>

namespace amls::app {

CLI::Validator in_range(const ParameterRange& range) {
  const std::string description =
      "[" + format_number(range.min) + ", " + format_number(range.max) + "]";
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size()) return "expected a number, got '" + text + "'";
        return range.contains(value) ? std::string() : out_of_range_text(value, range);
      },
      description, "RANGE");
}

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads, "worker threads (results do not depend on it)")
      ->check(in_range(ranges::kThreads))
      ->capture_default_str();
}

void add_variant_option(CLI::App& cmd, std::string& variant, bool ray_tracing) {
  std::vector<std::string> names{"exact", "interpolated"};
  std::string help = "resampler: exact (roots of F on grid edges)";
  if (ray_tracing) {
    names.push_back("raytrace");
    help += ", interpolated (zeros of the linear interpolant) or raytrace (the ray-tracing baseline of Gois et al. 2008)";
  } else {
    help += " or interpolated (zeros of the linear interpolant)";
  }
  cmd.add_option("--variant", variant, help)->check(CLI::IsMember(names))->capture_default_str();
}

void add_radius_factor_option(CLI::App& cmd, double& radius_factor) {
  cmd.add_option("--radius-factor", radius_factor, "influence radius Delta in units of h")
      ->check(in_range(ranges::kRadiusFactor))
      ->capture_default_str();
}

void add_rims_option(CLI::App& cmd, bool& keep_rims) {
  cmd.add_option("--rims", keep_rims,
                 "open surfaces keep their rims: rim samples are found, carried into the new points and marked there "
                 "(a PLY output keeps the marks, so that resampling it keeps its rim), and no point is placed beyond "
                 "the rim line they draw (off: the paper's resampler, which extends an open surface's rim by up to a "
                 "support at every resample; a closed surface is the same either way)")
      ->capture_default_str();
}

void add_flow_test_options(CLI::App& cmd, FlowTestConfig& config) {
  add_radius_factor_option(cmd, config.radius_factor);
  cmd.add_option("--min-weight", config.min_weight, "F is undefined where the neighbours' weights sum to less than this")
      ->check(in_range(ranges::kMinWeight))
      ->capture_default_str();
  cmd.add_option("--bias-correction", config.bias_correction,
                 "3D: correct F by the points' smoothed, limited offsets from it, removing the sphere fit's outward "
                 "bias on thin sheets and tubes (no effect in 2D or with raytrace)")
      ->capture_default_str();
  add_rims_option(cmd, config.keep_rims);
  cmd.add_option("--dt", config.dt, "time between resamplings")->check(in_range(ranges::kTimeStep))->capture_default_str();
  cmd.add_option("--substeps", config.substeps, "RK4 steps per dt")
      ->check(in_range(ranges::kSubsteps))
      ->capture_default_str();
  cmd.add_option("--ray-samples", config.ray.samples_per_cell,
                 "raytrace: samples of F per cell along each ray (2: every h/2)")
      ->check(in_range(ranges::kRaySamples))
      ->capture_default_str();
  cmd.add_option("--cluster-threshold", config.ray.cluster_threshold,
                 "raytrace: candidates closer than this many h to a kept one are removed")
      ->check(in_range(ranges::kClusterThreshold))
      ->capture_default_str();
}

CLI::Option* add_resample_option(CLI::App& cmd, std::string& policy) {
  return cmd
      .add_option("--resample", policy,
                  "when to resample: always (after every step, as the paper), auto (when a point is not surrounded "
                  "by neighbours of its sheet within 2.5 h, or normals turn faster than on a circle of radius "
                  "1.4 h), every:K (steps 0, K, 2K, ...) or local (after every step, only where the deformation "
                  "strained the sampling: docs/local-resampling.md)")
      ->capture_default_str();
}

}  // namespace amls::app
