#include "app/editor/region_tool.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <variant>

#include "app/editor/lasso.hpp"
#include "app/editor/picking.hpp"

namespace amls::editor {

namespace {

glm::vec3 to_glm(const Vec<3>& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

Vec<3> to_vec(const glm::vec3& v) { return Vec<3>(v.x, v.y, v.z); }

Mat<3> rotation_of(const Vec<3>& rotation) {
  const double angle = rotation.norm();
  return angle == 0.0 ? Mat<3>::Identity() : Mat<3>(Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix());
}

Vec<3> rotation_vector(const Mat<3>& rotation) {
  const Eigen::AngleAxisd turn(rotation);
  return turn.angle() * turn.axis();
}

// Fewer pixels than this between lasso corners add no corner.
constexpr float kLassoStepPx = 3.0f;

}  // namespace

RegionView moved_region(const RegionView& view, const command::RegionMove& motion) {
  // From where the view shows the members back to rest, then to the new motion.
  const Mat<3> before = view.motion.scale * rotation_of(view.motion.rotation);
  const Mat<3> after = motion.scale * rotation_of(motion.rotation);
  const Mat<3> change = after * before.inverse();
  RegionView out = view;
  out.motion = motion;
  out.centre = view.rest_centre + motion.translation;
  for (Vec<3>& m : out.members) m = out.centre + change * (m - view.centre);
  return out;
}

RegionTool::RegionTool(std::function<void(Command)> post) : post_(std::move(post)) {}

void RegionTool::sync(const std::vector<RegionView>& regions) {
  if (drag_) return;
  regions_ = regions;
  if (active_ && *active_ >= regions_.size()) active_.reset();
}

void RegionTool::start() {
  lasso_.clear();
  stroke_.reset();
  hover_.reset();
  drag_.reset();
  active_.reset();
  move_pending_ = false;
}

bool RegionTool::on_event(const InputEvent& event, const Viewport& viewport, glm::vec2 pixels_per_unit,
                          const Camera& camera, const std::vector<Vec<3>>& handles) {
  const glm::vec2 pixel = event.position * pixels_per_unit;
  if (event.type == InputEvent::Type::cursor) {
    if (!lasso_.empty()) {
      if (glm::distance(lasso_.back(), pixel) >= kLassoStepPx) lasso_.push_back(pixel);
      return true;
    }
    if (stroke_) {
      stroke_->paint(screen_grid(stroke_->shared_points(), camera, viewport), camera, pixel, pick_radius_px_);
      return true;
    }
    if (drag_) {
      drag_to(pixel, camera, viewport);
      return true;
    }
    if (brush_mode) hover(pixel, camera, viewport);  // the view may orbit on too
    return false;
  }
  if (event.type != InputEvent::Type::button || event.code != GLFW_MOUSE_BUTTON_LEFT) return false;
  if (event.action == GLFW_RELEASE) {
    if (!lasso_.empty()) {
      finish_lasso(camera, viewport);
      return true;
    }
    if (stroke_) {
      finish_stroke();
      return true;
    }
    if (drag_) {
      update();  // a move in the release's frame is the drag's last: send it
      drag_.reset();
      return true;
    }
    return false;
  }
  if (event.action != GLFW_PRESS || busy()) return false;
  if (brush_mode && !(event.mods & GLFW_MOD_ALT)) {
    if (!points_ || points_->size() == 0 || !(brush_radius() > 0.0)) return false;
    stroke_.emplace(points_, static_cast<float>(brush_radius()));
    // Off the surface there is nothing to paint: the press is the view's (an orbit in 3D).
    if (!stroke_->paint(screen_grid(points_, camera, viewport), camera, pixel, pick_radius_px_)) {
      stroke_.reset();
      return false;
    }
    return true;
  }
  if ((event.mods & GLFW_MOD_ALT) || lasso_mode) {
    if (!points_) return false;
    lasso_.push_back(pixel);
    return true;
  }
  // Shift+click adds a point handle, even on a marker.
  if ((event.mods & GLFW_MOD_SHIFT) && !(event.mods & GLFW_MOD_CONTROL)) return false;
  return grab_region(pixel, event.mods, camera, viewport, handles);
}

bool RegionTool::on_ring(glm::vec2 pixel, const Camera& camera, const Viewport& viewport) const {
  if (!ring_shown()) return false;
  const glm::vec3 marker = camera.to_window(to_glm(regions_[*active_].centre), viewport);
  if (marker.z < 0.0f || marker.z > 1.0f) return false;
  return std::abs(glm::distance(glm::vec2(marker), pixel) - ring_radius_px()) <= kRingReachPicks * pick_radius_px_;
}

bool RegionTool::grab_region(glm::vec2 pixel, int mods, const Camera& camera, const Viewport& viewport,
                             const std::vector<Vec<3>>& handles) {
  // A region's marker under the cursor (the nearest), else the active region's ring.
  std::vector<glm::vec3> markers;
  for (const RegionView& r : regions_) markers.push_back(to_glm(r.centre));
  std::optional<std::size_t> hit = pick_handle(markers, camera, viewport, pixel, pick_radius_px_);
  const bool ring = !hit && on_ring(pixel, camera, viewport);
  if (ring) hit = active_;
  if (!hit) return false;
  active_ = hit;
  if (regions_[*hit].pinned) return true;  // selected, but it stays put
  Drag drag;
  drag.index = *hit;
  drag.start = regions_[*hit];
  drag.handles = handles;
  const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0, shift = (mods & GLFW_MOD_SHIFT) != 0;
  drag.by_ring = ring;
  drag.gesture = (ring || (ctrl && !shift)) ? Gesture::rotate : (ctrl ? Gesture::scale : Gesture::translate);
  const glm::vec3 centre = to_glm(drag.start.centre);
  const std::optional<glm::vec3> under = plane_point(camera, viewport, pixel, centre);
  if (!under) return true;
  drag.grab = *under;
  // The axis through the marker toward the viewer: the plane of the drag (parallel to the screen) turns in itself.
  drag.axis = camera.mode == Camera::Mode::planar ? glm::vec3(0, 0, 1) : glm::normalize(camera.eye() - camera.target);
  drag_ = std::move(drag);
  return true;
}

std::string_view RegionTool::drag_gesture() const {
  if (!drag_) return "none";
  switch (drag_->gesture) {
    case Gesture::translate:
      return "move";
    case Gesture::rotate:
      return drag_->by_ring ? "ring" : "turn";
    case Gesture::scale:
      return "scale";
  }
  return "none";
}

void RegionTool::drag_to(glm::vec2 pixel, const Camera& camera, const Viewport& viewport) {
  Drag& d = *drag_;
  const glm::vec3 centre = to_glm(d.start.centre);
  const std::optional<glm::vec3> under = plane_point(camera, viewport, pixel, centre);
  if (!under) return;
  command::RegionMove motion = d.start.motion;
  const Vec<3> from = to_vec(d.grab - centre), to = to_vec(*under - centre);
  switch (d.gesture) {
    case Gesture::translate:
      motion.translation += to - from;
      if (camera.mode == Camera::Mode::planar) motion.translation.z() = d.start.motion.translation.z();
      break;
    case Gesture::rotate: {
      const Vec<3> axis = to_vec(d.axis);
      const double angle = std::atan2(from.cross(to).dot(axis), from.dot(to));
      const Mat<3> turned = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * rotation_of(d.start.motion.rotation);
      motion.rotation = rotation_vector(turned);
      break;
    }
    case Gesture::scale:
      if (from.norm() > 0.0 && to.norm() > 0.0) motion.scale = std::clamp(d.start.motion.scale * to.norm() / from.norm(), 1e-3, 1e3);
      break;
  }
  if (!d.moved) {
    d.moved = true;
    post_(command::BeginDrag{});
  }
  regions_[d.index] = moved_region(d.start, motion);
  move_pending_ = true;
}

void RegionTool::update() {
  if (!move_pending_ || !drag_) return;
  move_pending_ = false;
  command::MoveHandles move{drag_->handles, {}};
  for (const RegionView& r : regions_) move.regions.push_back(r.motion);
  post_(std::move(move));
}

bool RegionTool::cancel() {
  if (!lasso_.empty() || stroke_) {
    lasso_.clear();
    stroke_.reset();
    return true;
  }
  if (!drag_) return false;
  if (drag_->moved) {
    regions_[drag_->index] = drag_->start;
    post_(command::CancelDrag{});
  }
  drag_.reset();
  move_pending_ = false;
  return true;
}

std::vector<Vec<3>> RegionTool::selected_positions(std::span<const std::size_t> ids) const {
  std::vector<Vec<3>> out;
  out.reserve(ids.size());
  for (const std::size_t i : ids) out.push_back(to_vec(points_->positions[i]));
  return out;
}

void RegionTool::finish_lasso(const Camera& camera, const Viewport& viewport) {
  std::vector<glm::vec2> polygon = std::move(lasso_);
  lasso_.clear();
  if (!points_ || polygon.size() < 3) return;
  // Subtracting, the members inside the lasso go, whichever way they face.
  const std::vector<std::size_t> inside =
      lasso_select(screen_grid(points_, camera, viewport), points_->positions, points_->normals, camera, polygon);
  apply_selection(inside, [&](const Vec<3>& m) {
    const glm::vec3 w = camera.to_window(to_glm(m), viewport);
    return w.z >= 0.0f && w.z <= 1.0f && inside_polygon(polygon, glm::vec2(w.x, w.y));
  });
}

void RegionTool::finish_stroke() {
  const BrushStroke stroke = std::move(*stroke_);
  stroke_.reset();
  // Subtracting, the members within the brush's sphere about any place it was put down go.
  apply_selection(stroke.painted(), [&](const Vec<3>& m) { return stroke.covers(to_glm(m)); });
}

void RegionTool::apply_selection(std::span<const std::size_t> ids, const std::function<bool(const Vec<3>&)>& taken) {
  post_edit(selection_command(edit, active_, regions_, selected_positions(ids), taken));
}

void RegionTool::post_edit(std::optional<Command> change) {
  if (!change) return;
  if (std::holds_alternative<command::AddRegion>(*change)) {
    active_ = regions_.size();  // the worker appends it
  } else if (const auto* removed = std::get_if<command::RemoveRegion>(&*change)) {
    regions_.erase(regions_.begin() + static_cast<std::ptrdiff_t>(removed->index));
    active_.reset();
  }
  post_(std::move(*change));
}

const ScreenGrid& RegionTool::screen_grid(const std::shared_ptr<const PreparedPoints>& points, const Camera& camera,
                                          const Viewport& viewport) {
  if (!screen_ || screen_points_.lock() != points || !screen_->made_for(camera, viewport)) {
    // Cells of a third of the pick radius: a pick looks at the points of about 7 x 7 cells.
    screen_.emplace(points->positions, camera, viewport, std::max(2.0f, pick_radius_px_ / 3.0f));
    screen_points_ = points;
  }
  return *screen_;
}

void RegionTool::hover(glm::vec2 pixel, const Camera& camera, const Viewport& viewport) {
  hover_.reset();
  if (!points_ || points_->size() == 0) return;
  if (const std::optional<std::size_t> under = pick_point(screen_grid(points_, camera, viewport), points_->positions,
                                                          points_->normals, camera, pixel, pick_radius_px_))
    hover_ = points_->positions[*under];
}

void RegionTool::set_pinned(bool pinned) {
  if (!active_ || busy()) return;
  regions_[*active_].pinned = pinned;
  post_(command::PinRegion{*active_, pinned});
}

void RegionTool::remove_active() {
  if (busy()) return;
  post_edit(clearing_command(regions_, active_));
}

void RegionTool::invert_active(double reach) {
  if (!active_ || busy() || !points_) return;
  post_edit(inversion_command(regions_, *active_, points_->positions, reach));
}

}  // namespace amls::editor
