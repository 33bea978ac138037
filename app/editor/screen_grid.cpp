#include "app/editor/screen_grid.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace amls::editor {

namespace {

// The cells reach this far past the viewport's edges, so that a pick near an
// edge, or a brush that pokes just past it, stays within them.
constexpr float kMarginPx = 64.0f;

glm::mat4 clip_from_world(const Camera& camera, const Viewport& viewport) {
  return camera.projection(viewport.aspect()) * camera.view();
}

// The cell of a pixel coordinate along one axis: -1 before the first, `count` after the last.
int cell_along(float pixel, float origin, float cell_px, int count) {
  const float c = std::floor((pixel - origin) / cell_px);
  if (!(c >= 0.0f)) return -1;  // NaN too
  return c >= static_cast<float>(count) ? count : static_cast<int>(c);
}

}  // namespace

ScreenGrid::ScreenGrid(std::span<const glm::vec3> positions, const Camera& camera, const Viewport& viewport,
                       float cell_px)
    : clip_from_world_(clip_from_world(camera, viewport)), viewport_(viewport), cell_px_(cell_px) {
  if (viewport.width <= 0 || viewport.height <= 0) throw std::invalid_argument("a screen grid needs a viewport");
  if (!(cell_px > 0.0f) || !std::isfinite(cell_px))
    throw std::invalid_argument("a screen grid's cells must be a finite number of pixels > 0, got " +
                                std::to_string(cell_px));
  if (positions.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("a screen grid holds fewer than 2^32 points");
  origin_ = glm::vec2(-kMarginPx);
  columns_ = static_cast<int>(std::ceil((static_cast<float>(viewport.width) + 2.0f * kMarginPx) / cell_px));
  rows_ = static_cast<int>(std::ceil((static_cast<float>(viewport.height) + 2.0f * kMarginPx) / cell_px));
  const std::size_t cells = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);

  // Project every point once; its cell, or `cells` for those outside.
  window_.resize(positions.size());
  std::vector<std::uint32_t> cell_of(positions.size());
  cell_start_.assign(cells + 1, 0);
  const glm::vec2 size(static_cast<float>(viewport.width), static_cast<float>(viewport.height));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec4 clip = clip_from_world_ * glm::vec4(positions[i], 1.0f);
    std::size_t cell = cells;
    if (clip.w > 0.0f) {
      const glm::vec3 ndc = glm::vec3(clip) / clip.w;
      window_[i] = glm::vec3((ndc.x * 0.5f + 0.5f) * size.x, (0.5f - ndc.y * 0.5f) * size.y, ndc.z * 0.5f + 0.5f);
      const int column = cell_along(window_[i].x, origin_.x, cell_px_, columns_);
      const int row = cell_along(window_[i].y, origin_.y, cell_px_, rows_);
      if (column >= 0 && column < columns_ && row >= 0 && row < rows_)
        cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(column);
    } else {
      window_[i] = glm::vec3(0.0f, 0.0f, 2.0f);  // as Camera::to_window: behind the eye
    }
    cell_of[i] = static_cast<std::uint32_t>(cell);
    if (cell < cells) ++cell_start_[cell + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  ids_.resize(cell_start_[cells]);
  std::vector<std::uint32_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (cell_of[i] < cells)
      ids_[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
    else
      outside_.push_back(static_cast<std::uint32_t>(i));
  }
}

bool ScreenGrid::made_for(const Camera& camera, const Viewport& viewport) const {
  return viewport.x == viewport_.x && viewport.y == viewport_.y && viewport.width == viewport_.width &&
         viewport.height == viewport_.height && clip_from_world(camera, viewport) == clip_from_world_;
}

std::optional<ScreenGrid::Box> ScreenGrid::sphere_box(const glm::vec3& centre, float radius) const {
  const glm::vec2 size(static_cast<float>(viewport_.width), static_cast<float>(viewport_.height));
  glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-lo);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 offset((corner & 1) ? radius : -radius, (corner & 2) ? radius : -radius,
                           (corner & 4) ? radius : -radius);
    const glm::vec4 clip = clip_from_world_ * glm::vec4(centre + offset, 1.0f);
    if (!(clip.w > 0.0f)) return std::nullopt;
    const glm::vec2 pixel((clip.x / clip.w * 0.5f + 0.5f) * size.x, (0.5f - clip.y / clip.w * 0.5f) * size.y);
    lo = glm::min(lo, pixel);
    hi = glm::max(hi, pixel);
  }
  return Box{lo, hi};
}

bool ScreenGrid::reaches_outside(const Box& box) const {
  const glm::vec2 end = origin_ + cell_px_ * glm::vec2(static_cast<float>(columns_), static_cast<float>(rows_));
  return !(box.first.x >= origin_.x && box.first.y >= origin_.y && box.second.x < end.x && box.second.y < end.y);
}

std::pair<glm::ivec2, glm::ivec2> ScreenGrid::cells_of(const Box& box) const {
  const glm::ivec2 lo(std::max(0, cell_along(box.first.x, origin_.x, cell_px_, columns_)),
                      std::max(0, cell_along(box.first.y, origin_.y, cell_px_, rows_)));
  const glm::ivec2 hi(std::min(columns_ - 1, cell_along(box.second.x, origin_.x, cell_px_, columns_)),
                      std::min(rows_ - 1, cell_along(box.second.y, origin_.y, cell_px_, rows_)));
  return {lo, hi};
}

}  // namespace amls::editor
