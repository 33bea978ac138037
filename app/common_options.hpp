#pragma once
// Options that several commands share, defined once so their names, checks
// and help stay the same everywhere.
#include <CLI/CLI.hpp>
#include <string>

namespace amls::app {

void add_threads_option(CLI::App& cmd, int& threads);
void add_variant_option(CLI::App& cmd, std::string& variant);
void add_radius_factor_option(CLI::App& cmd, double& radius_factor);

}  // namespace amls::app
