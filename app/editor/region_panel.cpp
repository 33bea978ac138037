#include "app/editor/region_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace amls::editor {

namespace {

// Drawing more members than this per region only costs: every k-th is drawn.
constexpr std::size_t kMostDotsDrawn = 20000;

ImU32 region_colour(std::size_t index, bool pinned, float alpha) {
  // Pinned regions blue, moving ones in warm colours that differ from region to region.
  static const ImVec4 kMoving[] = {{1.0f, 0.45f, 0.1f, 1}, {0.95f, 0.2f, 0.6f, 1}, {0.9f, 0.8f, 0.1f, 1}};
  const ImVec4 c = pinned ? ImVec4(0.3f, 0.6f, 1.0f, 1) : kMoving[index % 3];
  return ImGui::GetColorU32(ImVec4(c.x, c.y, c.z, alpha));
}

}  // namespace

void draw_region_overlay(const RegionTool& tool, const Camera& camera, const Viewport& viewport,
                         glm::vec2 pixels_per_unit) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const auto to_screen = [&](const Vec<3>& x, bool& visible) {
    const glm::vec3 w =
        camera.to_window(glm::vec3(static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z())),
                         viewport);
    visible = w.z >= 0.0f && w.z <= 1.0f;
    return ImVec2(w.x / pixels_per_unit.x, w.y / pixels_per_unit.y);
  };
  const float dot = 1.5f;
  for (std::size_t r = 0; r < tool.regions().size(); ++r) {
    const RegionView& region = tool.regions()[r];
    const bool active = tool.active() == r;
    const ImU32 colour = region_colour(r, region.pinned, active ? 0.8f : 0.55f);
    const std::size_t stride = std::max<std::size_t>(1, region.members.size() / kMostDotsDrawn);
    for (std::size_t i = 0; i < region.members.size(); i += stride) {
      bool visible = false;
      const ImVec2 p = to_screen(region.members[i], visible);
      if (visible) draw->AddRectFilled(ImVec2(p.x - dot, p.y - dot), ImVec2(p.x + dot, p.y + dot), colour);
    }
    bool visible = false;
    const ImVec2 c = to_screen(region.centre, visible);
    if (!visible) continue;
    const float ring = 9.0f;
    const ImU32 marker = region_colour(r, region.pinned, 1.0f);
    draw->AddCircle(c, ring, marker, 24, active ? 3.0f : 1.5f);
    if (region.pinned) {
      draw->AddLine(ImVec2(c.x - ring, c.y - ring), ImVec2(c.x + ring, c.y + ring), marker, 1.5f);
      draw->AddLine(ImVec2(c.x - ring, c.y + ring), ImVec2(c.x + ring, c.y - ring), marker, 1.5f);
    } else {
      draw->AddCircleFilled(c, 3.0f, marker);
    }
    if (active && tool.ring_shown()) {
      // The turning ring, in the plane of the screen; bolder while it turns the region.
      const bool turning = tool.drag_gesture() == "ring";
      draw->AddCircle(c, tool.ring_radius_px() / pixels_per_unit.x, region_colour(r, false, turning ? 1.0f : 0.7f), 64,
                      turning ? 3.0f : 2.0f);
    }
  }
  // The brush stroke's points, in the selection's own colour, and the brush's sphere where it would paint.
  const ImU32 selecting = IM_COL32(120, 255, 200, 220);
  if (const std::optional<BrushStroke>& stroke = tool.stroke()) {
    const std::span<const std::size_t> painted = stroke->painted();
    const std::size_t stride = std::max<std::size_t>(1, painted.size() / kMostDotsDrawn);
    for (std::size_t k = 0; k < painted.size(); k += stride) {
      const glm::vec3 x = stroke->points().positions[painted[k]];
      bool visible = false;
      const ImVec2 p = to_screen(Vec<3>(x.x, x.y, x.z), visible);
      if (visible) draw->AddRectFilled(ImVec2(p.x - dot, p.y - dot), ImVec2(p.x + dot, p.y + dot), selecting);
    }
  }
  if (const std::optional<glm::vec3> at = tool.brush_hover()) {
    // The sphere's outline: its radius along the screen's right.
    const glm::mat4 view = camera.view();
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
    const glm::vec3 edge = *at + static_cast<float>(tool.brush_radius()) * right;
    bool visible = false, edge_visible = false;
    const ImVec2 c = to_screen(Vec<3>(at->x, at->y, at->z), visible);
    const ImVec2 e = to_screen(Vec<3>(edge.x, edge.y, edge.z), edge_visible);
    if (visible) draw->AddCircle(c, std::hypot(e.x - c.x, e.y - c.y), selecting, 48, 1.5f);
  }
  const std::span<const glm::vec2> lasso = tool.lasso();
  if (lasso.size() >= 2) {
    std::vector<ImVec2> corners;
    for (const glm::vec2& p : lasso) corners.emplace_back(p.x / pixels_per_unit.x, p.y / pixels_per_unit.y);
    draw->AddPolyline(corners.data(), static_cast<int>(corners.size()), IM_COL32(255, 255, 255, 220),
                      ImDrawFlags_Closed, 1.5f);
  }
}

ControlCentres draw_region_window(RegionTool& tool, double reach) {
  ControlCentres centres;
  // The centre of the control just drawn, as `name`.
  auto note = [&](const char* name) {
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    centres.emplace_back(name, glm::vec2(0.5f * (lo.x + hi.x), 0.5f * (lo.y + hi.y)));
  };
  const ImGuiIO& io = ImGui::GetIO();
  const float margin = ImGui::GetStyle().WindowPadding.x;
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - margin, io.DisplaySize.y - 3.0f * ImGui::GetFontSize()),
                          ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("Regions", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::Checkbox("Lasso (or Alt+drag)", &tool.lasso_mode);
  note("lasso");
  ImGui::SameLine();
  ImGui::Checkbox("Brush (B)", &tool.brush_mode);
  note("brush");
  if (tool.brush_mode) {
    ImGui::SetNextItemWidth(8.0f * ImGui::GetFontSize());
    ImGui::SliderFloat("radius / h ([ ])", &tool.brush_radius_h, kBrushRadiusH.first, kBrushRadiusH.second, "%.1f",
                       ImGuiSliderFlags_Logarithmic);
  }
  int edit = static_cast<int>(tool.edit);
  ImGui::RadioButton("new", &edit, 0);
  note("new");
  ImGui::SameLine();
  ImGui::RadioButton("add", &edit, 1);
  note("add");
  ImGui::SameLine();
  ImGui::RadioButton("subtract", &edit, 2);
  note("subtract");
  tool.edit = static_cast<SelectionEdit>(edit);
  const std::size_t count = tool.regions().size();
  ImGui::Text("%zu region%s%s", count, count == 1 ? "" : "s",
              count > 0 ? ": drag a marker (Ctrl: turn, Ctrl+Shift: scale)" : "");
  if (tool.ring_shown()) ImGui::TextUnformatted("drag the ring about the active marker: turn it");
  if (const std::optional<std::size_t> active = tool.active(); active && *active < count) {
    const RegionView& region = tool.regions()[*active];
    ImGui::Text("region %zu: %zu points", *active + 1, region.members.size());
    bool pinned = region.pinned;
    if (ImGui::Checkbox("pinned (P)", &pinned)) tool.set_pinned(pinned);
    note("pinned");
    ImGui::SameLine();
    if (ImGui::Button("invert")) tool.invert_active(reach);
    note("invert");
    ImGui::SameLine();
    if (ImGui::Button("clear")) tool.remove_active();
    note("clear");
  }
  ImGui::End();
  return centres;
}

}  // namespace amls::editor
