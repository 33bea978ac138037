#include "app/editor/brush_stroke.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "app/editor/lasso.hpp"
#include "app/editor/picking.hpp"

namespace amls::editor {

BrushStroke::BrushStroke(std::shared_ptr<const PreparedPoints> points, float radius)
    : points_(std::move(points)), radius_(radius) {
  if (!points_ || points_->size() == 0) throw std::invalid_argument("a brush needs points to paint");
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw std::invalid_argument("a brush's radius must be a finite number > 0, got " + std::to_string(radius));
  marked_.assign(points_->size(), 0);
}

bool BrushStroke::paint(const ScreenGrid& grid, const Camera& camera, glm::vec2 pixel, float pick_radius_px) {
  if (grid.size() != points_->size())
    throw std::invalid_argument("a brush's screen grid holds " + std::to_string(grid.size()) + " points, its surface " +
                                std::to_string(points_->size()));
  const std::optional<std::size_t> under =
      pick_point(grid, points_->positions, points_->normals, camera, pixel, pick_radius_px);
  if (!under) return false;
  const glm::vec3 centre = points_->positions[*under];
  // A stroke dragged slowly puts the brush down at nearly the same place many
  // times: a tenth of the radius from the last place adds nothing new worth a pass.
  if (!centres_.empty() && glm::distance(centres_.back(), centre) < 0.1f * radius_) return true;
  centres_.push_back(centre);
  for (const std::size_t i : brush_select(grid, points_->positions, points_->normals, camera, centre, radius_)) {
    if (marked_[i]) continue;
    marked_[i] = 1;
    painted_.push_back(i);
  }
  return true;
}

bool BrushStroke::covers(const glm::vec3& x) const {
  for (const glm::vec3& c : centres_)
    if (glm::distance(c, x) <= radius_) return true;
  return false;
}

}  // namespace amls::editor
