#include "app/common_options.hpp"

namespace amls::app {

void add_threads_option(CLI::App& cmd, int& threads) {
  cmd.add_option("--threads", threads, "worker threads (results do not depend on it)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

void add_variant_option(CLI::App& cmd, std::string& variant) {
  cmd.add_option("--variant", variant,
                 "resampler: exact (roots of F on grid edges) or interpolated (zeros of the linear interpolant)")
      ->check(CLI::IsMember({"exact", "interpolated"}))
      ->capture_default_str();
}

void add_radius_factor_option(CLI::App& cmd, double& radius_factor) {
  cmd.add_option("--radius-factor", radius_factor, "influence radius Delta in units of h")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

}  // namespace amls::app
