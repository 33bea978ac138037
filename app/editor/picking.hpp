#pragma once
// Screen-space picking and handle dragging for the editor's view: which point
// or handle is under the cursor, and where a dragged handle goes. Pixels are
// those of the viewport, x right and y down from its top-left corner (as
// Camera::to_window). No GL: only the camera's matrices.
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/screen_grid.hpp"
#include "render/camera.hpp"

namespace amls::editor {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit length
};

// The ray from the eye through a pixel (planar views: straight down -z).
Ray pixel_ray(const Camera& camera, const Viewport& viewport, glm::vec2 pixel);

// The point nearest to `pixel` on screen, within `radius_px` - or within the
// size on screen of a splat of radius `world_radius` around it, if that is
// larger (zoomed in, a click anywhere on a splat picks its point). Of points at
// about the same distance on screen, one facing the viewer and near the eye
// wins, so a click on a closed surface picks its front. `normals` may be empty.
std::optional<std::size_t> pick_point(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                      const Camera& camera, const Viewport& viewport, glm::vec2 pixel, float radius_px,
                                      float world_radius = 0.0f);
// The same among the points `grid` (made for `camera`, of `positions`) finds
// within `radius_px` of `pixel`: it looks at those points only.
std::optional<std::size_t> pick_point(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera, glm::vec2 pixel,
                                      float radius_px);

// The handle nearest to `pixel` on screen within `radius_px`.
std::optional<std::size_t> pick_handle(std::span<const glm::vec3> handles, const Camera& camera,
                                       const Viewport& viewport, glm::vec2 pixel, float radius_px);

enum class AxisLock { none, x, y, z };

// Where a handle dragged from `start` goes when the cursor is at `pixel`: on the
// plane through `start` parallel to the screen (2D: the plane z = 0), offset by
// `grab` (the handle minus the plane point under the cursor at mouse-down), and
// with an axis lock, only along that axis. Nothing if the ray misses the plane.
std::optional<glm::vec3> drag_position(const Camera& camera, const Viewport& viewport, glm::vec2 pixel,
                                       const glm::vec3& start, const glm::vec3& grab, AxisLock lock);

// The point under `pixel` on the plane through `anchor` parallel to the screen.
std::optional<glm::vec3> plane_point(const Camera& camera, const Viewport& viewport, glm::vec2 pixel,
                                     const glm::vec3& anchor);

}  // namespace amls::editor
