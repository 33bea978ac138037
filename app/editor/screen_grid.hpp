#pragma once
// A surface's points bucketed by where they fall on screen, for one camera and
// viewport: what lets the brush, and the pick under the cursor that places it,
// look only at the points near the cursor instead of projecting every point at
// each mouse move. Made in one pass over the points (a counting sort by pixel
// cell), and made again only when the camera, the viewport or the points
// change. Pixels as in picking.hpp. No GL: only the camera's matrices.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "render/camera.hpp"

namespace amls::editor {

class ScreenGrid {
 public:
  // A pixel box: its least and greatest corners.
  using Box = std::pair<glm::vec2, glm::vec2>;

  // Throws std::invalid_argument for an empty viewport, a cell that is not a
  // finite number of pixels > 0, or more points than 32-bit ids hold.
  ScreenGrid(std::span<const glm::vec3> positions, const Camera& camera, const Viewport& viewport, float cell_px);

  // Whether the grid was made for this camera and viewport (the same matrices).
  bool made_for(const Camera& camera, const Viewport& viewport) const;
  std::size_t size() const { return window_.size(); }
  const Viewport& viewport() const { return viewport_; }
  // Point i's window position and depth, as Camera::to_window gives them.
  const glm::vec3& window(std::size_t i) const { return window_[i]; }

  // Calls fn(i) for every point whose window position lies in `box`, and for
  // some others: those in the cells the box touches, and when the box reaches
  // past the cells (which cover the viewport and a margin about it), every
  // point beyond them or behind the eye. `box` nothing: every point.
  template <typename Fn>
  void for_each_in(const std::optional<Box>& box, Fn&& fn) const {
    if (!box || reaches_outside(*box)) {
      for (const std::uint32_t i : outside_) fn(std::size_t{i});
    }
    const auto [lo, hi] = box ? cells_of(*box) : std::pair{glm::ivec2(0), glm::ivec2(columns_ - 1, rows_ - 1)};
    for (int row = lo.y; row <= hi.y; ++row) {
      const std::size_t first = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_);
      for (std::uint32_t k = cell_start_[first + static_cast<std::size_t>(lo.x)];
           k < cell_start_[first + static_cast<std::size_t>(hi.x + 1)]; ++k)
        fn(std::size_t{ids_[k]});
    }
  }

  // The pixel box that holds the image of a sphere (that of the cube about it);
  // nothing if the cube reaches behind the eye (every point may then lie in it).
  std::optional<Box> sphere_box(const glm::vec3& centre, float radius) const;

 private:
  bool reaches_outside(const Box& box) const;
  // The cells [lo, hi] the box touches, clamped to the grid (empty when lo > hi).
  std::pair<glm::ivec2, glm::ivec2> cells_of(const Box& box) const;

  glm::mat4 clip_from_world_{1.0f};
  Viewport viewport_;
  float cell_px_ = 1.0f;
  glm::vec2 origin_{0.0f};  // the pixel at the first cell's least corner
  int columns_ = 0, rows_ = 0;
  std::vector<glm::vec3> window_;
  // The ids of the points in the cells, row by row; cell c's are
  // ids_[cell_start_[c], cell_start_[c + 1]).
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> ids_;
  std::vector<std::uint32_t> outside_;  // beyond the cells, or behind the eye
};

}  // namespace amls::editor
