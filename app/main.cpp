// amls: the command line of the AMLS deforming-surface toolkit.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "app/commands.hpp"
#include "core/util/interrupt.hpp"

int main(int argc, char** argv) {
  // Ctrl+C stops the running work; commands write their outputs only once it is done.
  amls::stop_work_on_interrupt();
  CLI::App app{
      "amls - deforming point-set (AMLS) surfaces with grid-based resampling\n"
      "(Resampling Strategies for Deforming MLS Surfaces). Run 'amls <command> --help' for a command's options."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "amls 0.1.0");
  amls::app::add_flow_test_commands(app);
  amls::app::add_compare_command(app);
  amls::app::add_bench_command(app);
  amls::app::add_deform_command(app);
  amls::app::add_resample_command(app);
  amls::app::add_render_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    // The work stopped on Ctrl+C, whether it says so (amls::Cancelled) or a
    // step wrapped the stop in its own message.
    if (amls::interrupt_requested()) {
      std::cerr << "\namls: interrupted: stopped without writing any output\n";
      return amls::kInterruptedExitStatus;
    }
    std::cerr << "amls: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
