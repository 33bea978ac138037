#pragma once
// One stroke of the editor's brush selection: at each cursor position the
// surface point under the cursor is picked, and every point within the
// brush's radius of it (a sphere, in world units) is painted; in 3D only the
// points that face the viewer, so that a brush on a closed surface does not
// reach through to its back. The painted points are what the stroke selects
// on release (region_tool.hpp says what is done with them). No GL.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <vector>

#include "app/editor/screen_grid.hpp"
#include "render/camera.hpp"
#include "render/point_data.hpp"

namespace amls::editor {

class BrushStroke {
 public:
  // Throws std::invalid_argument for no points or a radius that is not a finite number > 0.
  BrushStroke(std::shared_ptr<const PreparedPoints> points, float radius);

  // Paints about the point under `pixel` (nearest on screen within
  // `pick_radius_px`, front first); false if there is none. `grid`, made of
  // points() for `camera`, finds the points: a dab costs in proportion to
  // those near it on screen, not to the surface's. Throws
  // std::invalid_argument for a grid of another number of points.
  bool paint(const ScreenGrid& grid, const Camera& camera, glm::vec2 pixel, float pick_radius_px);

  const PreparedPoints& points() const { return *points_; }
  const std::shared_ptr<const PreparedPoints>& shared_points() const { return points_; }
  float radius() const { return radius_; }
  // The points painted so far (indices into points()), in the order painted.
  std::span<const std::size_t> painted() const { return painted_; }
  // Where the brush was put down: the picked points.
  std::span<const glm::vec3> centres() const { return centres_; }
  // Whether x lies within the radius of a centre (what a subtracting stroke takes from a region).
  bool covers(const glm::vec3& x) const;

 private:
  std::shared_ptr<const PreparedPoints> points_;
  float radius_;
  std::vector<std::uint8_t> marked_;  // 1 for each painted point
  std::vector<std::size_t> painted_;
  std::vector<glm::vec3> centres_;
};

}  // namespace amls::editor
