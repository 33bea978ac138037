#pragma once
// The editor's ImGui panels: the side panel (shape and file, surface,
// deformation, display, messages), the live Table 1 in the top-right corner,
// the status bar and the help window. They read the newest snapshot and the worker's status, and act
// through PanelActions.
#include <functional>

#include "app/editor/snapshot.hpp"
#include "app/editor/ui_state.hpp"
#include "app/editor/view_controller.hpp"

namespace amls::editor {

struct PanelActions {
  std::function<void(Command)> post;
  std::function<void()> export_points;  // Ctrl+S
  std::function<void()> export_mesh;    // the Export mesh button
  std::function<void()> save_scene;     // Ctrl+Shift+S
  std::function<void()> screenshot;     // F12
  std::function<void()> fit_view;       // F
};

void draw_side_panel(UiState& ui, const Snapshot& snapshot, const WorkerStatus& status, ViewController& view,
                     const PanelActions& actions);
void draw_table1(const Snapshot& snapshot);
void draw_status_bar(const UiState& ui, const Snapshot& snapshot, const WorkerStatus& status,
                     const ViewController& view);
void draw_help(UiState& ui);

}  // namespace amls::editor
