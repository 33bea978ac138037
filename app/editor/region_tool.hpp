#pragma once
// Region handles in the editor's view (core/deform/region_handle.hpp):
// selecting a part of the surface and moving it as one piece.
//
// - Alt+drag (or any left drag while the lasso mode is on) draws a lasso; on
//   release the points inside it that face the viewer become a new region,
//   or are added to or taken from the active one (the edit mode).
// - A left drag that starts on the surface while the brush mode is on paints
//   with a sphere of the brush's radius (brush_stroke.hpp); on release the
//   painted points are taken as a lasso's are. One that starts off the
//   surface is not the tool's: the view orbits.
// - A drag of a region's centre marker moves the region: plain, it
//   translates in the plane parallel to the screen; with Ctrl it turns about
//   the view axis by the angle swept around the marker; with Ctrl+Shift it
//   scales by the ratio of the distances from the marker. A pinned region
//   does not move.
// - The active moving region has a ring about its marker, in the plane
//   parallel to the screen: a drag that starts on the ring turns the region
//   about the axis through the marker toward the viewer by the angle swept
//   around it, as a rotate gizmo's view ring does (no key needed).
// What a selection does to the regions is region_selection.hpp's. Region
// edits become worker commands; while a drag runs the regions shown are the
// tool's own, so that they follow the cursor at once. No GL.
#include <algorithm>
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "app/editor/brush_stroke.hpp"
#include "app/editor/command.hpp"
#include "app/editor/editor_window.hpp"
#include "app/editor/region_moves.hpp"
#include "app/editor/region_selection.hpp"
#include "app/editor/screen_grid.hpp"
#include "render/camera.hpp"
#include "render/point_data.hpp"

namespace amls::editor {

// The brush's radius, in units of h, lies in this range.
inline constexpr std::pair<float, float> kBrushRadiusH{0.5f, 50.0f};

class RegionTool {
 public:
  explicit RegionTool(std::function<void(Command)> post);

  void set_points(std::shared_ptr<const PreparedPoints> points) { points_ = std::move(points); }
  // The worker's regions; taken unless a drag runs.
  void sync(const std::vector<RegionView>& regions);
  // A new shape: no lasso, no drag, no active region.
  void start();

  // One event the UI did not take; true if the tool used it. `handles` are
  // the point handles as the view has them (a region move sends them along).
  bool on_event(const InputEvent& event, const Viewport& viewport, glm::vec2 pixels_per_unit, const Camera& camera,
                const std::vector<Vec<3>>& handles);
  // Once per frame: the newest drag position to the worker.
  void update();
  // Esc: a region drag goes back to mouse-down, a lasso is dropped. False if there was neither.
  bool cancel();

  // The active region: pinned or let go, removed, inverted (the points of
  // `points` farther than `reach` from it become its members).
  void set_pinned(bool pinned);
  void remove_active();
  void invert_active(double reach);

  bool lasso_mode = false;  // a plain left drag draws a lasso
  bool brush_mode = false;  // a plain left drag paints with the brush (before the lasso mode)
  float brush_radius_h = 4.0f;  // the brush's radius in units of h
  SelectionEdit edit = SelectionEdit::new_region;
  // The grid spacing h: the brush's unit.
  void set_spacing(double h) { spacing_ = h; }
  double brush_radius() const { return brush_radius_h * spacing_; }
  // The brush's radius times `factor`, kept within kBrushRadiusH.
  void scale_brush(float factor) {
    brush_radius_h = std::clamp(brush_radius_h * factor, kBrushRadiusH.first, kBrushRadiusH.second);
  }

  std::optional<std::size_t> active() const { return active_; }
  void set_active(std::optional<std::size_t> index) { active_ = index; }
  bool busy() const { return drag_.has_value() || !lasso_.empty() || stroke_.has_value(); }
  const std::vector<RegionView>& regions() const { return regions_; }
  std::span<const glm::vec2> lasso() const { return lasso_; }
  // The brush stroke being painted, if any.
  const std::optional<BrushStroke>& stroke() const { return stroke_; }
  // In brush mode, the surface point under the cursor (where the brush would paint).
  std::optional<glm::vec3> brush_hover() const { return brush_mode ? hover_ : std::nullopt; }
  // How near (framebuffer pixels) the cursor must come to a marker to grab it.
  void set_pick_radius(float pixels) { pick_radius_px_ = pixels; }
  // The turning ring's radius about the active region's marker, framebuffer pixels.
  float ring_radius_px() const { return kRingRadiusPicks * pick_radius_px_; }
  // Whether the active region shows its turning ring (it is a moving one).
  bool ring_shown() const { return active_ && *active_ < regions_.size() && !regions_[*active_].pinned; }
  // What the running marker or ring drag does, for the debug log: "move",
  // "turn" (Ctrl), "ring", "scale" (Ctrl+Shift); "none" if none runs.
  std::string_view drag_gesture() const;

 private:
  enum class Gesture { translate, rotate, scale };
  // The ring's radius in pick radii, and how near it a press must land (also in pick radii).
  static constexpr float kRingRadiusPicks = 4.0f;
  static constexpr float kRingReachPicks = 0.5f;
  struct Drag {
    std::size_t index = 0;
    Gesture gesture = Gesture::translate;
    bool by_ring = false;  // a rotation started on the ring
    RegionView start;      // the region at mouse-down
    glm::vec3 grab{0.0f};  // the plane point under the cursor at mouse-down
    glm::vec3 axis{0.0f};  // the view axis (rotate)
    std::vector<Vec<3>> handles;
    bool moved = false;  // the worker has a BeginDrag
  };

  // A press at `pixel` on a marker or the active region's ring: the drag it starts.
  bool grab_region(glm::vec2 pixel, int mods, const Camera& camera, const Viewport& viewport,
                   const std::vector<Vec<3>>& handles);
  // Whether `pixel` lies on the active region's ring.
  bool on_ring(glm::vec2 pixel, const Camera& camera, const Viewport& viewport) const;
  void finish_lasso(const Camera& camera, const Viewport& viewport);
  void finish_stroke();
  // The points `ids` become a new region, or are added to the active one; or,
  // subtracting, the active region's members for which `taken` holds go.
  void apply_selection(std::span<const std::size_t> ids, const std::function<bool(const Vec<3>&)>& taken);
  // Posts a region edit, and keeps the tool's own regions and active one in step with it.
  void post_edit(std::optional<Command> change);
  // The screen grid of `points` for this view: the last one, or a new one if
  // the view or the points changed (a stroke keeps the points it started on).
  const ScreenGrid& screen_grid(const std::shared_ptr<const PreparedPoints>& points, const Camera& camera,
                                const Viewport& viewport);
  void hover(glm::vec2 pixel, const Camera& camera, const Viewport& viewport);
  void drag_to(glm::vec2 pixel, const Camera& camera, const Viewport& viewport);
  std::vector<Vec<3>> selected_positions(std::span<const std::size_t> ids) const;

  std::function<void(Command)> post_;
  std::shared_ptr<const PreparedPoints> points_;
  std::vector<RegionView> regions_;
  std::optional<std::size_t> active_;
  std::vector<glm::vec2> lasso_;
  std::optional<BrushStroke> stroke_;
  std::optional<glm::vec3> hover_;
  std::optional<ScreenGrid> screen_;
  std::weak_ptr<const PreparedPoints> screen_points_;  // the points screen_ holds
  double spacing_ = 0.0;
  std::optional<Drag> drag_;
  bool move_pending_ = false;
  float pick_radius_px_ = 12.0f;
};

// The region moved by `motion` from where `view` shows it.
RegionView moved_region(const RegionView& view, const command::RegionMove& motion);

}  // namespace amls::editor
