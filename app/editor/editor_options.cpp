#include "app/editor/editor_options.hpp"

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "core/util/parameter_ranges.hpp"

namespace amls::editor {

namespace {

// The smallest window side the panels still fit in.
constexpr int kMinWindowSide = 64;

}  // namespace

std::optional<int> parse_editor_options(int argc, char** argv, EditorOptions& options) {
  CLI::App app{
      "amls-editor - drag handles and watch a point-set (AMLS) surface deform and resample live.\n"
      "Press H in the window for the keyboard and mouse controls."};
  app.set_version_flag("--version", "amls-editor 0.1.0");
  std::string size;
  app.add_option("input", options.input, "point set (.ply, .off, .xyz, .pwn, .csv, .txt; normals estimated where missing), mesh (.obj, .stl, .ply, .off) or scene (.json) to open");
  std::string normals = "given";
  app.add_option("--normals", normals,
                 "given: a point set's own normals, broken ones mended; estimated: set aside and estimated as for "
                 "a set without, for a scan whose normals are unoriented (also the file browser's 'Estimate "
                 "normals'; Save Scene records it as the shape's \"normals\": \"estimated\")")
      ->check(CLI::IsMember({"given", "estimated"}))
      ->capture_default_str();
  app.add_flag("--3d", options.start_3d, "start with the built-in sphere instead of the circle (no input)");
  app.add_option("--export", options.export_path, "where Ctrl+S writes the point set (.ply with normals, or .xyz)");
  app.add_option("--scene-out", options.scene_path, "where Save Scene (Ctrl+Shift+S) writes the session");
  app.add_option("--screenshot", options.screenshot_path, "where F12 writes the window as PNG");
  app.add_option("--size", size, "window size WxH in screen units (default 1280x800)");
  app.add_option("--ui-scale", options.ui_scale, "scale of fonts and widgets (default: the monitor's)")
      ->check(CLI::Range(0.5, 4.0));
  app.add_option("--threads", options.threads, "threads of the surface's work (default: cores - 1)")
      ->check(CLI::Range(1, 256));
  app.add_option("--debug-log", options.debug_log,
                 "write a line per frame and per event to this file (or set AMLS_EDITOR_DEBUG_LOG)");
  try {
    app.parse(argc, argv);
    if (!size.empty()) {
      try {
        const ImageSize window = parse_image_size(size, "--size", kMinWindowSide);
        options.width = window.width;
        options.height = window.height;
      } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError(e.what());
      }
    }
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  options.estimate_normals = normals == "estimated";
  if (options.debug_log.empty())
    if (const char* env = std::getenv("AMLS_EDITOR_DEBUG_LOG")) options.debug_log = env;
  const std::string stem = options.input.empty() ? (options.start_3d ? "sphere" : "circle")
                                                 : std::filesystem::path(options.input).stem().string();
  if (options.export_path.empty()) options.export_path = stem + "-edited.ply";
  if (options.scene_path.empty()) options.scene_path = stem + "-session.json";
  return std::nullopt;
}

}  // namespace amls::editor
