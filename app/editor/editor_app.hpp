#pragma once
// amls-editor's main loop on the main thread: the window, ImGui, every GL call
// and the view; the surface work happens on the EditorWorker's thread. Each
// frame takes the newest snapshot (uploading it only when it is new), turns
// input into commands, draws the surface and the panels, and never waits for
// the worker.
#include <cstdint>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "app/editor/debug_log.hpp"
#include "app/editor/editor_options.hpp"
#include "app/editor/editor_window.hpp"
#include "app/editor/editor_worker.hpp"
#include "app/editor/file_browser.hpp"
#include "app/editor/panels.hpp"
#include "app/editor/region_panel.hpp"
#include "app/editor/region_tool.hpp"
#include "app/editor/ui_state.hpp"
#include "app/editor/view_controller.hpp"
#include "render/splat_renderer.hpp"

namespace amls::editor {

class EditorApp {
 public:
  // Opens the window; throws std::runtime_error without a display or GL 3.3.
  explicit EditorApp(const EditorOptions& options);
  ~EditorApp();
  int run();

 private:
  void frame();
  void post(Command command);
  void take_messages();
  void take_snapshot();
  void process_input();
  void on_key(const InputEvent& event);
  RenderOptions render_options() const;
  void write_screenshot();
  void export_points();
  void export_mesh();
  void save_scene();
  void fit_view();
  void log_view();
  void log_regions();
  // Where the region window's controls are, when that changes.
  void log_region_window(const ControlCentres& centres);
  double wait_timeout() const;

  EditorOptions options_;
  DebugLog log_;
  EditorWindow window_;
  std::unique_ptr<SplatRenderer> renderer_;
  UiState ui_;
  ViewController view_;
  RegionTool regions_;
  std::string last_regions_;
  std::string last_region_window_;
  FileBrowser browser_;
  std::shared_ptr<const Snapshot> shown_;
  std::uint64_t last_posted_ = 0;
  std::uint64_t frames_ = 0;
  bool screenshot_requested_ = false;
  std::vector<std::future<Message>> background_;  // PNG files being written
  std::string last_view_;
  // Last: the worker's thread stops before anything it could call back into goes away.
  std::unique_ptr<EditorWorker> worker_;
};

}  // namespace amls::editor
