#pragma once
// amls-editor's command line.
#include <optional>
#include <string>

namespace amls::editor {

struct EditorOptions {
  std::string input;            // a point-set file or a scene; empty: the built-in shape
  bool estimate_normals = false;  // --normals estimated: a point set's own normals set aside and estimated
  bool start_3d = false;        // --3d: the built-in sphere instead of the circle
  std::string export_path;      // Ctrl+S writes here (default: <input>-edited.ply)
  std::string scene_path;       // Save Scene writes here (default: <input>-session.json)
  std::string screenshot_path;  // F12 writes here (default: amls-editor-<time>.png)
  int width = 1280;
  int height = 800;
  float ui_scale = 0.0f;  // 0: the monitor's content scale
  int threads = 0;        // 0: one fewer than the cores (at least one)
  std::string debug_log;  // a line per frame and per event, for tests (also AMLS_EDITOR_DEBUG_LOG)
};

// Parses argv. Returns the exit code when the program should stop (after
// --help, --version or a bad argument, with the message printed), else nothing.
std::optional<int> parse_editor_options(int argc, char** argv, EditorOptions& options);

}  // namespace amls::editor
