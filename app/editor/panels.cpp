#include "app/editor/panels.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace amls::editor {

namespace {

const ImVec4 kWarning{1.0f, 0.78f, 0.3f, 1.0f};
const ImVec4 kError{1.0f, 0.42f, 0.38f, 1.0f};
const ImVec4 kDim{0.65f, 0.67f, 0.72f, 1.0f};

ImVec4 level_color(Message::Level level) {
  switch (level) {
    case Message::Level::warning:
      return kWarning;
    case Message::Level::error:
      return kError;
    case Message::Level::info:
      break;
  }
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

float status_bar_height() { return ImGui::GetFrameHeight() + 2.0f * ImGui::GetStyle().WindowPadding.y; }

// Point count and h of a built-in shape, and the button that loads it.
void builtin_shape(int dimension, const char* button, double radius, int& points, double& spacing,
                   const PanelActions& actions) {
  ImGui::PushID(dimension);
  ImGui::PushItemWidth(ImGui::GetFontSize() * 6.0f);
  ImGui::InputInt("points", &points, 0);
  ImGui::SameLine();
  ImGui::InputDouble("h", &spacing, 0.0, 0.0, "%.4g");
  ImGui::PopItemWidth();
  if (ImGui::Button(button))
    actions.post(
        command::LoadShape{dimension, radius, static_cast<std::size_t>(std::max(dimension + 1, points)), spacing});
  ImGui::PopID();
}

void shape_section(UiState& ui, const Snapshot& snapshot, const PanelActions& actions) {
  if (snapshot.dimension > 0) {
    ImGui::TextWrapped("%s", snapshot.name.c_str());
    ImGui::TextColored(kDim, "%dD, %zu points, %zu handles", snapshot.dimension, snapshot.points->input_count,
                       snapshot.handles.size());
  } else {
    ImGui::TextColored(kDim, "Nothing loaded");
  }
  if (ImGui::Button("Open... (Ctrl+O)")) ui.show_browser = true;
  ImGui::SameLine();
  ImGui::TextColored(kDim, "or drop a file here");
  if (ImGui::TreeNode("Built-in shapes")) {
    builtin_shape(2, "New circle (2D)", ui.circle_radius, ui.circle_points, ui.circle_spacing, actions);
    builtin_shape(3, "New sphere (3D)", ui.sphere_radius, ui.sphere_points, ui.sphere_spacing, actions);
    ImGui::TreePop();
  }
  ImGui::Separator();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##export", &ui.export_path);
  if (ImGui::Button("Export points (Ctrl+S)")) actions.export_points();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##mesh", &ui.mesh_path);
  if (ImGui::Button("Export mesh")) actions.export_mesh();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText("##scene", &ui.scene_path);
  if (ImGui::Button("Save Scene (Ctrl+Shift+S)")) actions.save_scene();
  ImGui::SameLine();
  ImGui::TextColored(kDim, "%zu steps", snapshot.recorded_steps);
  if (!snapshot.replay_note.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    ImGui::TextWrapped("Replay not exact: %s", snapshot.replay_note.c_str());
    ImGui::PopStyleColor();
  } else if (!snapshot.replay_arguments.empty() && snapshot.recorded_steps > 0) {
    ImGui::TextColored(kDim, "replay with amls deform %s", snapshot.replay_arguments.c_str());
  }
  if (ImGui::Button("Screenshot (F12)")) actions.screenshot();
  ImGui::SameLine();
  if (ImGui::Button("Fit view (F)")) actions.fit_view();
}

// Resampling on or off, and when: after every step, when the sampling
// quality leaves its band (auto), every K-th step, or after every step only
// where strained (local). One combo, so that "off" cannot be combined with a
// policy it ignores.
void resampling_switch(UiState& ui, const PanelActions& actions) {
  ResamplePolicy& policy = ui.edit.policy;
  // The combo's entries in the order of ResamplePolicy::Kind, then off.
  static const char* kWhen[] = {"always", "auto", "every K steps", "local", "off"};
  constexpr int kOff = 4;
  int when = ui.edit.resample ? static_cast<int>(policy.kind) : kOff;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
  bool changed = ImGui::Combo("resample", &when, kWhen, kOff + 1);
  ui.edit.resample = when != kOff;
  if (ui.edit.resample) policy.kind = static_cast<ResamplePolicy::Kind>(when);
  if (ui.edit.resample && policy.kind == ResamplePolicy::Kind::every) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 3.0f);
    ImGui::InputInt("K", &policy.every, 0);
    policy.every = std::max(1, policy.every);
    changed = ImGui::IsItemDeactivatedAfterEdit() || changed;
  }
  if (changed) actions.post(command::SetResampling{ui.edit.resample, policy});
  if (!ui.edit.resample)
    ImGui::TextColored(kWarning, "off: the points spread and S(P) breaks");
  else if (policy.kind == ResamplePolicy::Kind::automatic)
    ImGui::TextColored(kDim, "when a gap exceeds 2.5 h or a feature is sharper than 1.4 h");
  else if (policy.kind == ResamplePolicy::Kind::local)
    ImGui::TextColored(kDim, "only where a step strained the sampling");
}

void surface_section(UiState& ui, const PanelActions& actions) {
  ImGui::PushItemWidth(ImGui::GetFontSize() * 7.0f);
  bool grid =
      ImGui::InputDouble("grid spacing h", &ui.edit.spacing, 0.0, 0.0, "%.5g", ImGuiInputTextFlags_EnterReturnsTrue);
  grid = ImGui::IsItemDeactivatedAfterEdit() || grid;
  bool factor = ImGui::InputDouble("radius factor (Delta/h)", &ui.edit.radius_factor, 0.0, 0.0, "%.3g",
                                   ImGuiInputTextFlags_EnterReturnsTrue);
  factor = ImGui::IsItemDeactivatedAfterEdit() || factor;
  ImGui::PopItemWidth();
  if ((grid || factor) && ui.edit.spacing > 0.0 && ui.edit.radius_factor > 0.0)
    actions.post(command::SetGrid{ui.edit.spacing, ui.edit.radius_factor});
  ImGui::TextUnformatted("Resampling");
  ImGui::SameLine();
  int variant = ui.edit.variant == Variant::exact ? 0 : 1;
  bool toggled = ImGui::RadioButton("exact", &variant, 0);
  ImGui::SameLine();
  toggled = ImGui::RadioButton("interpolated (I)", &variant, 1) || toggled;
  if (toggled) {
    ui.edit.variant = variant == 0 ? Variant::exact : Variant::interpolated;
    actions.post(command::SetVariant{ui.edit.variant});
  }
  resampling_switch(ui, actions);
}

void deformation_section(UiState& ui, const Snapshot& snapshot, ViewController& view, const PanelActions& actions) {
  static const char* kKinds[] = {"affine", "similarity", "rigid"};
  int kind = static_cast<int>(ui.edit.kind);
  ImGui::PushItemWidth(ImGui::GetFontSize() * 7.0f);
  if (ImGui::Combo("MLS map", &kind, kKinds, 3)) {
    ui.edit.kind = static_cast<MlsKind>(kind);
    actions.post(command::SetDeformation{ui.edit.kind, ui.edit.alpha});
  }
  float alpha = static_cast<float>(ui.edit.alpha);
  if (ImGui::SliderFloat("alpha", &alpha, 0.5f, 3.0f, "%.2f")) ui.edit.alpha = alpha;
  if (ImGui::IsItemDeactivatedAfterEdit()) actions.post(command::SetDeformation{ui.edit.kind, ui.edit.alpha});
  ImGui::PopItemWidth();

  ImGui::Text("%zu handles", view.handles().size());
  if (const std::optional<std::size_t> selected = view.selected()) {
    const Vec<3>& h = view.handles()[*selected];
    ImGui::SameLine();
    if (snapshot.dimension == 3)
      ImGui::TextColored(kDim, "#%zu at (%.3f, %.3f, %.3f)", *selected, h.x(), h.y(), h.z());
    else
      ImGui::TextColored(kDim, "#%zu at (%.3f, %.3f)", *selected, h.x(), h.y());
    if (ImGui::SmallButton("Delete (Del)")) view.remove_selected();
  }
  ImGui::TextUnformatted("Drag lock");
  static const char* kLocks[] = {"free", "X", "Y", "Z"};
  for (int a = 0; a < (snapshot.dimension == 3 ? 4 : 3); ++a) {
    ImGui::SameLine();
    if (ImGui::RadioButton(kLocks[a], static_cast<int>(view.lock()) == a)) {
      if (a == 0 && view.lock() != AxisLock::none) view.toggle_lock(view.lock());
      if (a > 0) view.toggle_lock(static_cast<AxisLock>(a));
    }
  }
  ImGui::BeginDisabled(!snapshot.can_undo);
  if (ImGui::Button("Undo")) actions.post(command::Undo{});
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!snapshot.can_redo);
  if (ImGui::Button("Redo")) actions.post(command::Redo{});
  ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Reset shape")) actions.post(command::Reset{});
}

void display_section(UiState& ui, const Snapshot& snapshot, const PanelActions& actions) {
  RenderOptions& r = ui.render;
  if (snapshot.dimension == 3) {
    int dots = ui.dots_in_3d ? 1 : 0;
    ImGui::RadioButton("splats", &dots, 0);
    ImGui::SameLine();
    ImGui::RadioButton("points", &dots, 1);
    ui.dots_in_3d = dots == 1;
    ImGui::SameLine();
    ImGui::Checkbox("cull back faces", &r.cull_back_faces);
  }
  ImGui::Checkbox("surface", &r.show_points);
  ImGui::SameLine();
  ImGui::Checkbox("normals (N)", &r.show_normals);
  ImGui::SameLine();
  ImGui::Checkbox("handles", &r.show_handles);
  static const char* kColors[] = {"uniform", "normal", "sampling quality"};
  int color = static_cast<int>(r.color_mode);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 9.0f);
  if (ImGui::Combo("colour", &color, kColors, 3)) r.color_mode = static_cast<ColorMode>(color);
  if (r.color_mode == ColorMode::scalar) ImGui::TextColored(kDim, "nearest-neighbour spacing / h, 0 to 2");
  if (snapshot.dimension == 2) {
    if (ImGui::Checkbox("MLS curve (C)", &ui.show_curve)) actions.post(command::SetCurveTracing{ui.show_curve});
    ImGui::SameLine();
    ImGui::Checkbox("grid (G)", &r.show_grid);
  }
}

void table1_section(const Snapshot& snapshot) {
  const PhaseTimings& last = snapshot.last.timings;
  const PhaseTimings& total = snapshot.total;
  const double sum = total.total();
  struct Row {
    const char* name;
    double last, total;
  };
  // The paper's order for the proposed method.
  const Row rows[] = {{"Deform", last.deform, total.deform},          {"Update F", last.function, total.function},
                      {"Resample", last.resample, total.resample},    {"Hash", last.hash, total.hash},
                      {"Comp. Normals", last.normals, total.normals}, {"Total", last.total(), sum}};
  if (ImGui::BeginTable("table1", 4,
                        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingFixedFit)) {
    const float number = ImGui::CalcTextSize("00000.00").x;
    ImGui::TableSetupColumn("phase");
    ImGui::TableSetupColumn("last ms", ImGuiTableColumnFlags_WidthFixed, number);
    ImGui::TableSetupColumn("total s", ImGuiTableColumnFlags_WidthFixed, number);
    ImGui::TableSetupColumn("%", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("100.0").x);
    ImGui::TableHeadersRow();
    for (const Row& row : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(row.name);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", snapshot.has_last ? 1e3 * row.last : 0.0);
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", row.total);
      ImGui::TableNextColumn();
      ImGui::Text("%.1f", sum > 0.0 ? 100.0 * row.total / sum : 0.0);
    }
    ImGui::EndTable();
  }
  ImGui::Text("%zu steps, %zu resamples, %.0f steps/s, %zu points", snapshot.steps, snapshot.resamples,
              snapshot.steps_per_second, snapshot.points->input_count);
  if (snapshot.spacing_version == Snapshot::kNotMeasured)
    ImGui::TextColored(kDim, "spacing / h: measured once the drag pauses");
  else
    ImGui::TextColored(snapshot.spacing_version == snapshot.points_version ? ImGui::GetStyle().Colors[ImGuiCol_Text]
                                                                           : kDim,
                       "spacing / h: min %.2f  median %.2f  max %.2f%s", snapshot.spacing.min,
                       snapshot.spacing.median, snapshot.spacing.max,
                       snapshot.spacing_version == snapshot.points_version ? "" : " (before the last steps)");
  if (snapshot.has_last) {
    const std::size_t failed = snapshot.last.normals.failed();
    ImGui::TextColored(failed > 0 ? kWarning : kDim, "failed normal fits: %zu", failed);
    ImGui::TextColored(kDim, "F undefined at %zu of %zu vertices", snapshot.last.resample.undefined_vertices,
                       snapshot.last.resample.vertices);
  }
}

void progress(const WorkerStatus& status) {
  if (!status.busy || status.seconds < 0.1) return;
  const float fraction =
      status.phases > 0 ? (static_cast<float>(status.phase) + 0.5f) / static_cast<float>(status.phases) : 0.5f;
  const std::string text = status.activity + " " + std::to_string(status.phase + 1) + "/" +
                           std::to_string(std::max(1, status.phases)) + format(", %.1f s", status.seconds);
  ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), text.c_str());
}

}  // namespace

void draw_side_panel(UiState& ui, const Snapshot& snapshot, const WorkerStatus& status, ViewController& view,
                     const PanelActions& actions) {
  const ImGuiIO& io = ImGui::GetIO();
  const float width = std::min(24.0f * ImGui::GetFontSize(), 0.4f * io.DisplaySize.x);
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, io.DisplaySize.y - status_bar_height()));
  ImGui::Begin("amls editor", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  progress(status);
  if (ImGui::CollapsingHeader("Shape and file", ImGuiTreeNodeFlags_DefaultOpen)) shape_section(ui, snapshot, actions);
  if (ImGui::CollapsingHeader("Surface", ImGuiTreeNodeFlags_DefaultOpen)) surface_section(ui, actions);
  if (ImGui::CollapsingHeader("Deformation", ImGuiTreeNodeFlags_DefaultOpen))
    deformation_section(ui, snapshot, view, actions);
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) display_section(ui, snapshot, actions);
  if (ImGui::CollapsingHeader("Messages")) {
    for (const Message& m : ui.history) {
      ImGui::PushStyleColor(ImGuiCol_Text, level_color(m.level));
      ImGui::TextWrapped("%s", m.text.c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::End();
}

void draw_table1(const Snapshot& snapshot) {
  const ImGuiIO& io = ImGui::GetIO();
  const float margin = ImGui::GetStyle().WindowPadding.x;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - margin, margin), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("Table 1 (live)", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  table1_section(snapshot);
  ImGui::End();
}

void draw_status_bar(const UiState& ui, const Snapshot& snapshot, const WorkerStatus& status,
                     const ViewController& view) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = status_bar_height();
  ImGui::SetNextWindowPos(ImVec2(0.0f, io.DisplaySize.y - height));
  ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, height));
  ImGui::Begin("status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  std::string right;
  if (status.busy && status.seconds >= 0.1) right = status.activity + format(" %.1f s", status.seconds) + "  |  ";
  if (view.dragging() && view.lock() != AxisLock::none)
    right += std::string("lock ") + "-XYZ"[static_cast<int>(view.lock())] + "  |  ";
  if (snapshot.dimension > 0)
    right += std::to_string(snapshot.dimension) + "D  " + std::to_string(snapshot.points->input_count) + " points  h " +
             format("%.4g", snapshot.settings.spacing) + "  " + to_string(snapshot.settings.variant) +
             (!snapshot.settings.resample ? "  (no resampling)"
              : snapshot.settings.policy.kind == ResamplePolicy::Kind::always
                  ? ""
                  : "  resample " + snapshot.settings.policy.to_string());
  const float right_width = ImGui::CalcTextSize(right.c_str()).x;
  ImGui::PushStyleColor(ImGuiCol_Text, level_color(ui.status.level));
  ImGui::PushClipRect(ImGui::GetCursorScreenPos(),
                      ImVec2(io.DisplaySize.x - right_width - 3.0f * ImGui::GetFontSize(), io.DisplaySize.y), true);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(ui.status.text.c_str());
  ImGui::PopClipRect();
  ImGui::PopStyleColor();
  ImGui::SameLine(io.DisplaySize.x - right_width - ImGui::GetStyle().WindowPadding.x);
  ImGui::TextColored(kDim, "%s", right.c_str());
  ImGui::End();
}

void draw_help(UiState& ui) {
  if (!ui.show_help) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.5f * io.DisplaySize.x, 0.5f * io.DisplaySize.y), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::Begin("Keyboard and mouse (H)", &ui.show_help, ImGuiWindowFlags_AlwaysAutoResize);
  static const char* kControls[][2] = {
      {"Shift+click on the surface", "add a handle at the picked point"},
      {"click a handle", "select it"},
      {"drag a handle", "deform: 2D in the plane, 3D parallel to the screen"},
      {"X / Y / Z (while dragging too)", "lock the drag to an axis (again: free)"},
      {"Esc", "cancel the drag (back to mouse-down); else deselect"},
      {"Delete / Backspace", "remove the selected handle"},
      {"Ctrl+Z / Ctrl+Shift+Z (Ctrl+Y)", "undo / redo a drag or edit"},
      {"Ctrl+R", "reset to the initial shape"},
      {"Alt+drag", "lasso a region (Regions window: new / add / subtract)"},
      {"B, then drag on the surface; [ ]", "brush a region; its radius"},
      {"drag a region's marker", "move the region (Ctrl: turn, Ctrl+Shift: scale)"},
      {"drag the ring about the active marker", "turn the region toward the viewer"},
      {"P", "pin or let go the active region"},
      {"drag empty space (brush: off the surface)", "3D: orbit; 2D: pan"},
      {"right or middle drag", "pan (3D brush or lasso: middle orbits)"},
      {"mouse wheel", "zoom"},
      {"F", "fit the view"},
      {"I", "exact / interpolated resampling"},
      {"N / C / G", "normals / MLS curve / grid (2D)"},
      {"Ctrl+O, or drop a file", "open a point set (.ply, .xyz) or scene (.json)"},
      {"Ctrl+S", "export the points (PLY with normals, or XYZ)"},
      {"Ctrl+Shift+S", "save the session as a scene"},
      {"F12", "screenshot (PNG)"},
      {"H", "this help"},
      {"Ctrl+Q", "quit"},
  };
  if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& control : kControls) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(control[0]);
      ImGui::TableNextColumn();
      ImGui::TextColored(kDim, "%s", control[1]);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

}  // namespace amls::editor
