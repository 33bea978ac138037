#pragma once
// The editor's region handles on screen (Dear ImGui): each region's members
// as dots in its own colour over the view, its centre marker as a ring (the
// active one brighter, a pinned one with a cross; the active moving one with
// its turning ring about it), the lasso being drawn, the
// brush stroke's points in the selection's colour and the brush's sphere; and
// a small window to choose the lasso or the brush, the edit (new, add,
// subtract), and to pin, invert or clear the active region.
#include <string>
#include <utility>
#include <vector>

#include "app/editor/region_tool.hpp"

namespace amls::editor {

// `pixels_per_unit` converts ImGui's window units to framebuffer pixels.
void draw_region_overlay(const RegionTool& tool, const Camera& camera, const Viewport& viewport,
                         glm::vec2 pixels_per_unit);
// Where each of the region window's controls is on screen (window units): its
// label and its centre, for the debug log, so that a test can press them as a
// user would.
using ControlCentres = std::vector<std::pair<std::string, glm::vec2>>;

// `reach`: the distance within which a point belongs to a region (h), for Invert.
ControlCentres draw_region_window(RegionTool& tool, double reach);

}  // namespace amls::editor
