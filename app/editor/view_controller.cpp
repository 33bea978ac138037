#include "app/editor/view_controller.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace amls::editor {

namespace {

constexpr float kOrbitDegreesPerPixel = 0.3f;
constexpr float kZoomPerWheelStep = 1.15f;

glm::vec3 to_glm(const Vec<3>& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

Vec<3> to_vec(const glm::vec3& v) { return Vec<3>(v.x, v.y, v.z); }

}  // namespace

ViewController::ViewController(std::function<void(Command)> post) : post_(std::move(post)) {}

void ViewController::start(int dimension, const BoundingSphere& bounds, const Viewport& viewport) {
  dimension_ = dimension;
  camera_ = dimension == 2 ? Camera::planar() : Camera::orbit();
  drag_.reset();
  camera_drag_.reset();
  selected_.reset();
  hovered_.reset();
  lock_ = AxisLock::none;
  fit(bounds, viewport);
}

void ViewController::fit(const BoundingSphere& bounds, const Viewport& viewport) {
  if (bounds.empty() || viewport.width <= 0 || viewport.height <= 0) return;
  // A little more room than Camera::fit leaves, so the shape clears the status bar.
  camera_.fit(BoundingSphere{bounds.center, 1.12f * bounds.radius}, viewport.aspect());
}

void ViewController::set_points(std::shared_ptr<const PreparedPoints> points, float splat_radius) {
  points_ = std::move(points);
  splat_radius_ = splat_radius;
}

void ViewController::sync_handles(const std::vector<Vec<3>>& handles) {
  if (drag_) return;
  handles_ = handles;
  if (selected_ && *selected_ >= handles_.size()) selected_.reset();
  if (hovered_ && *hovered_ >= handles_.size()) hovered_.reset();
}

std::vector<glm::vec3> ViewController::handle_positions() const {
  std::vector<glm::vec3> out;
  for (const Vec<3>& h : handles_) out.push_back(to_glm(h));
  return out;
}

std::optional<std::size_t> ViewController::pick_surface(glm::vec2 pixel, const Viewport& viewport) const {
  if (!points_) return std::nullopt;
  return pick_point(points_->positions, points_->normals, camera_, viewport, pixel, pick_radius_px_, splat_radius_);
}

void ViewController::on_event(const InputEvent& event, const Viewport& viewport, glm::vec2 pixels_per_unit) {
  const glm::vec2 pixel = event.position * pixels_per_unit;
  switch (event.type) {
    case InputEvent::Type::button:
      if (event.action == GLFW_PRESS)
        press(event, pixel, viewport);
      else if (event.action == GLFW_RELEASE)
        release(event);
      break;
    case InputEvent::Type::cursor:
      move(pixel, viewport);
      break;
    case InputEvent::Type::scroll:
      zoom(event.scroll.y, pixel, viewport);
      break;
    case InputEvent::Type::key:
      break;
  }
}

void ViewController::press(const InputEvent& event, glm::vec2 pixel, const Viewport& viewport) {
  cursor_ = pixel;
  if (drag_ || camera_drag_) return;  // one interaction at a time
  if (event.code == GLFW_MOUSE_BUTTON_LEFT && (event.mods & GLFW_MOD_SHIFT)) {
    if (const std::optional<std::size_t> hit = pick_surface(pixel, viewport)) {
      const Vec<3> position = to_vec(points_->positions[*hit]);
      handles_.push_back(position);
      selected_ = handles_.size() - 1;
      post_(command::AddHandle{position});
    }
    return;
  }
  if (event.code == GLFW_MOUSE_BUTTON_LEFT) {
    if (const std::optional<std::size_t> hit =
            pick_handle(handle_positions(), camera_, viewport, pixel, 1.5f * pick_radius_px_)) {
      selected_ = hit;
      const glm::vec3 anchor = to_glm(handles_[*hit]);
      const std::optional<glm::vec3> under = plane_point(camera_, viewport, pixel, anchor);
      drag_ = HandleDrag{*hit, handles_, under ? anchor - *under : glm::vec3(0.0f), pixel, false};
      return;
    }
  }
  camera_drag_ = CameraDrag{event.code, pixel, pixel, false};
}

void ViewController::release(const InputEvent& event) {
  if (drag_ && event.code == GLFW_MOUSE_BUTTON_LEFT) {
    drag_.reset();
    return;
  }
  if (camera_drag_ && camera_drag_->button == event.code) {
    // A left click on empty space clears the selection.
    if (!camera_drag_->moved && event.code == GLFW_MOUSE_BUTTON_LEFT) selected_.reset();
    camera_drag_.reset();
  }
}

void ViewController::move(glm::vec2 pixel, const Viewport& viewport) {
  cursor_ = pixel;
  if (drag_) {
    if (!drag_->moved && glm::length(pixel - drag_->press) < 0.4f * pick_radius_px_) return;
    const glm::vec3 start = to_glm(drag_->start[drag_->index]);
    const AxisLock lock = dimension_ == 2 && lock_ == AxisLock::z ? AxisLock::none : lock_;
    const std::optional<glm::vec3> p = drag_position(camera_, viewport, pixel, start, drag_->grab, lock);
    if (!p) return;
    if (!drag_->moved) {
      drag_->moved = true;
      post_(command::BeginDrag{});
    }
    Vec<3> moved = to_vec(*p);
    if (dimension_ == 2) moved.z() = 0.0;
    // Unlocked axes of a locked drag keep their exact start values.
    for (int a = 0; a < 3; ++a)
      if (lock != AxisLock::none && a != static_cast<int>(lock) - 1) moved[a] = drag_->start[drag_->index][a];
    handles_[drag_->index] = moved;
    move_pending_ = true;
    return;
  }
  if (!camera_drag_) return;
  const glm::vec2 delta = pixel - camera_drag_->last;
  camera_drag_->last = pixel;
  if (glm::length(pixel - camera_drag_->press) > 3.0f) camera_drag_->moved = true;
  const bool orbits = camera_drag_->button == GLFW_MOUSE_BUTTON_LEFT ||
                      (middle_orbits_ && camera_drag_->button == GLFW_MOUSE_BUTTON_MIDDLE);
  if (dimension_ == 3 && orbits)
    camera_.orbit_by(-delta.x * kOrbitDegreesPerPixel, delta.y * kOrbitDegreesPerPixel);
  else
    camera_.pan_by_pixels(delta, viewport);
}

void ViewController::zoom(float steps, glm::vec2 pixel, const Viewport& viewport) {
  if (steps == 0.0f) return;
  const float factor = std::pow(kZoomPerWheelStep, steps);
  if (dimension_ == 2) {
    // Keep the point under the cursor where it is.
    const std::optional<glm::vec3> before = plane_point(camera_, viewport, pixel, glm::vec3(0.0f));
    camera_.zoom_by(factor);
    const std::optional<glm::vec3> after = plane_point(camera_, viewport, pixel, glm::vec3(0.0f));
    if (before && after) camera_.target += glm::vec3(before->x - after->x, before->y - after->y, 0.0f);
    return;
  }
  camera_.zoom_by(factor);
}

void ViewController::update(const Viewport& viewport, bool shift_down, bool cursor_over_ui) {
  hovered_.reset();
  preview_.reset();
  const bool in_view = !cursor_over_ui && cursor_.x >= 0.0f && !camera_drag_;
  if (!drag_ && in_view) {
    hovered_ = pick_handle(handle_positions(), camera_, viewport, cursor_, 1.5f * pick_radius_px_);
    if (shift_down && !hovered_)
      if (const std::optional<std::size_t> hit = pick_surface(cursor_, viewport)) preview_ = points_->positions[*hit];
  }
  if (move_pending_ && drag_) post_(command::MoveHandles{handles_, {}});
  move_pending_ = false;
}

void ViewController::cancel() {
  if (drag_) {
    if (drag_->moved) {
      handles_ = drag_->start;
      post_(command::CancelDrag{});
    }
    drag_.reset();
    move_pending_ = false;
    return;
  }
  selected_.reset();
}

void ViewController::remove_selected() {
  if (!selected_ || drag_ || *selected_ >= handles_.size()) return;
  post_(command::RemoveHandle{*selected_});
  handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(*selected_));
  selected_.reset();
}

void ViewController::toggle_lock(AxisLock axis) { lock_ = lock_ == axis ? AxisLock::none : axis; }

std::vector<Handle> ViewController::drawn_handles() const {
  std::vector<Handle> out;
  for (std::size_t i = 0; i < handles_.size(); ++i) {
    const bool selected = selected_ == i, hovered = hovered_ == i || (drag_ && drag_->index == i);
    const HandleState state = selected ? (hovered ? HandleState::selected_hovered : HandleState::selected)
                                       : (hovered ? HandleState::hovered : HandleState::idle);
    out.push_back(Handle{to_glm(handles_[i]), state});
  }
  if (preview_) out.push_back(Handle{*preview_, HandleState::hovered});
  return out;
}

}  // namespace amls::editor
