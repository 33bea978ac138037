#pragma once
// Each command registers its subcommand and options on the CLI.
#include <CLI/CLI.hpp>

namespace amls::app {

void add_compare_command(CLI::App& app);
void add_deform_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_flow_test_commands(CLI::App& app);
void add_render_command(CLI::App& app);
void add_resample_command(CLI::App& app);

}  // namespace amls::app
