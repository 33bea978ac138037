#pragma once
// Selecting points of the surface on screen: a lasso (a polygon of pixels)
// and a brush (a sphere around a picked point), both taking only the points
// that face the viewer in 3D, so that a selection on a closed surface takes
// its front. Pixels as in picking.hpp. No GL: only the camera's matrices.
#include <cstddef>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "app/editor/screen_grid.hpp"
#include "render/camera.hpp"

namespace amls::editor {

// Whether `p` lies inside the polygon (even-odd rule; the last corner joins the first).
bool inside_polygon(std::span<const glm::vec2> polygon, glm::vec2 p);

// The points whose position on screen lies inside `polygon`; in 3D (normals
// given) only those facing the eye. `grid` (made for `camera`, of
// `positions`) finds them: only the points in the polygon's box are looked
// at. In the order of their indices.
std::vector<std::size_t> lasso_select(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera,
                                      std::span<const glm::vec2> polygon);

// The points within `radius` of `centre`; in 3D (normals given) only those
// facing the eye. `grid` (made for `camera`, of `positions`) finds them: only
// the points whose image lies in the sphere's are looked at. In the order of
// their indices.
std::vector<std::size_t> brush_select(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera, const glm::vec3& centre,
                                      float radius);

}  // namespace amls::editor
