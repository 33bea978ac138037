#pragma once
// What the editor's panels edit and show, kept between frames (main thread).
#include <deque>
#include <string>

#include "app/editor/snapshot.hpp"
#include "render/render_options.hpp"

namespace amls::editor {

struct UiState {
  RenderOptions render;
  bool dots_in_3d = false;  // 3D points as small dots instead of splats
  bool show_curve = true;   // 2D: the MLS curve

  std::string export_path;
  std::string mesh_path;  // Export mesh writes here (.obj, .ply, .stl)
  std::string scene_path;
  std::string screenshot_path;

  // The parameter widgets; taken from each snapshot whose settings changed.
  SurfaceSettings edit;
  SurfaceSettings seen;
  bool seen_any = false;

  // Built-in shapes.
  int circle_points = 250;
  double circle_radius = 1.0;
  double circle_spacing = 0.024;
  int sphere_points = 10000;
  double sphere_radius = 1.0;
  double sphere_spacing = 0.04;

  bool show_help = false;
  bool show_browser = false;
  // Point-set files opened from the browser or dropped on the window: their own
  // normals set aside and estimated (`--normals estimated`).
  bool estimate_normals = false;

  Message status{Message::Level::info, "Shift+click on the surface adds a handle; drag it to deform. H: help"};
  std::deque<Message> history;  // newest first

  void tell(Message message) {
    status = message;
    history.push_front(std::move(message));
    if (history.size() > 50) history.pop_back();
  }
};

}  // namespace amls::editor
