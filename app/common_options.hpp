#pragma once
// Options that several commands share, defined once so their names, checks
// and help stay the same everywhere.
#include <CLI/CLI.hpp>
#include <string>

#include "core/run/flow_test.hpp"
#include "core/util/parameter_ranges.hpp"

namespace amls::app {

// Checks an option's value against one of core/util/parameter_ranges.hpp's
// ranges, with the same message as a scene's key: "--KEY: must be within [MIN,
// MAX] (MEANING), got VALUE". Non-numbers and NaN are refused.
CLI::Validator in_range(const ParameterRange& range);

void add_threads_option(CLI::App& cmd, int& threads);
// --variant: exact or interpolated (the grid walk); with `ray_tracing`, also
// raytrace (the ray-tracing baseline, for the flow tests).
void add_variant_option(CLI::App& cmd, std::string& variant, bool ray_tracing = false);
void add_radius_factor_option(CLI::App& cmd, double& radius_factor);
// --rims on|off: whether an open surface keeps its rims (AmlsParameters::keep_rims).
void add_rims_option(CLI::App& cmd, bool& keep_rims);
// The options of a flow test's configuration other than --grid, --variant and
// --threads: --radius-factor, --min-weight, --bias-correction, --rims, --dt,
// --substeps and the ray tracer's --ray-samples and --cluster-threshold.
void add_flow_test_options(CLI::App& cmd, FlowTestConfig& config);
// --resample always|auto|every:K|local (core/resample/resample_policy.hpp); the command
// parses it with ResamplePolicy::parse before its work, whose message names
// the option. Returns the option, for excludes().
CLI::Option* add_resample_option(CLI::App& cmd, std::string& policy);

}  // namespace amls::app
