#pragma once
// Mouse and keyboard in the editor's view: the camera (3D: orbit with the left
// button, pan with the right or middle one - or orbit with the middle one while
// the left paints or draws a lasso; 2D: pan with any; the wheel zooms),
// and the handles - Shift+click on the surface adds one at the picked point,
// a click selects, a drag moves it (2D: in the plane; 3D: in the plane through
// it parallel to the screen; X, Y, Z lock an axis), Delete removes it, Esc
// cancels a drag. Handle edits become worker commands; the handles shown are
// the controller's own, so that a drag follows the cursor at once while the
// surface catches up.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/command.hpp"
#include "app/editor/editor_window.hpp"
#include "app/editor/picking.hpp"
#include "render/point_data.hpp"
#include "render/render_options.hpp"

namespace amls::editor {

class ViewController {
 public:
  // `post` sends a command to the worker.
  explicit ViewController(std::function<void(Command)> post);

  // A new shape: a planar camera in 2D, an orbit looking down -z in 3D, framed on `bounds`.
  void start(int dimension, const BoundingSphere& bounds, const Viewport& viewport);
  void fit(const BoundingSphere& bounds, const Viewport& viewport);

  // The surface's points for picking, as drawn (a new handle goes where its
  // point is drawn), shared with the snapshot that holds them; `splat_radius`
  // (world units, 0 for none) lets a click anywhere on a splat pick it.
  void set_points(std::shared_ptr<const PreparedPoints> points, float splat_radius);
  // The worker's handles; taken unless a drag is running (the caller knows the
  // worker has applied every command sent).
  void sync_handles(const std::vector<Vec<3>>& handles);

  // One event the UI did not take. `pixels_per_unit` converts window units to
  // framebuffer pixels; `viewport` is the framebuffer's.
  void on_event(const InputEvent& event, const Viewport& viewport, glm::vec2 pixels_per_unit);
  // Once per frame after the events: hover, the Shift preview, and the newest drag position to the worker.
  void update(const Viewport& viewport, bool shift_down, bool cursor_over_ui);

  // Keys that act on the view.
  void cancel();                    // Esc: a running drag goes back to mouse-down, else the selection clears
  void remove_selected();           // Delete
  void toggle_lock(AxisLock axis);  // X, Y, Z

  // How near (framebuffer pixels) the cursor must come to a point or handle to pick it.
  void set_pick_radius(float pixels) { pick_radius_px_ = pixels; }

  const Camera& camera() const { return camera_; }
  Camera& camera() { return camera_; }
  int dimension() const { return dimension_; }
  bool dragging() const { return drag_.has_value(); }
  // Whether a button drag is moving the camera.
  bool moving_camera() const { return camera_drag_.has_value(); }
  // In 3D the middle button orbits instead of panning: set while a left drag
  // paints or draws a lasso, so that the view can still turn.
  void set_middle_orbits(bool orbits) { middle_orbits_ = orbits; }
  AxisLock lock() const { return lock_; }
  const std::vector<Vec<3>>& handles() const { return handles_; }
  std::optional<std::size_t> selected() const { return selected_; }
  // The handles to draw, with their hover and selection states; the Shift preview last.
  std::vector<Handle> drawn_handles() const;

 private:
  struct HandleDrag {
    std::size_t index = 0;
    std::vector<Vec<3>> start;  // every handle at mouse-down
    glm::vec3 grab{0.0f};       // handle minus the plane point under the cursor at mouse-down
    glm::vec2 press{0.0f};      // pixel
    bool moved = false;         // past the click threshold: the worker has a BeginDrag
  };
  struct CameraDrag {
    int button = 0;
    glm::vec2 last{0.0f};
    glm::vec2 press{0.0f};
    bool moved = false;
  };

  void press(const InputEvent& event, glm::vec2 pixel, const Viewport& viewport);
  void release(const InputEvent& event);
  void move(glm::vec2 pixel, const Viewport& viewport);
  void zoom(float steps, glm::vec2 pixel, const Viewport& viewport);
  std::optional<std::size_t> pick_surface(glm::vec2 pixel, const Viewport& viewport) const;
  std::vector<glm::vec3> handle_positions() const;

  std::function<void(Command)> post_;
  Camera camera_ = Camera::planar();
  int dimension_ = 2;
  std::shared_ptr<const PreparedPoints> points_;
  std::vector<Vec<3>> handles_;
  std::optional<std::size_t> selected_, hovered_;
  std::optional<glm::vec3> preview_;  // Shift: where a click would add a handle
  std::optional<HandleDrag> drag_;
  std::optional<CameraDrag> camera_drag_;
  bool move_pending_ = false;
  AxisLock lock_ = AxisLock::none;
  glm::vec2 cursor_{-1.0f};
  float pick_radius_px_ = 8.0f;
  float splat_radius_ = 0.0f;
  bool middle_orbits_ = false;
};

}  // namespace amls::editor
