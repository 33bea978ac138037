#pragma once
// The view of the scene: a 3D turntable orbit in perspective, or a 2D planar view
// in orthographic projection. Plain data plus the matrices it implies; saved and
// restored as JSON so that a view can be kept.
//
// Default 3D view (azimuth 0, elevation 0): the eye on +z of the target, looking
// down -z, with +y up and +x to the right. Azimuth turns the eye about +y
// (positive: towards +x), elevation raises it towards +y.
// 2D view: x to the right, y up, looking down -z at the plane z = 0.
#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>
#include <span>

#include "render/render_options.hpp"

namespace amls {

// A sphere enclosing a scene; radius < 0 means empty.
struct BoundingSphere {
  glm::vec3 center{0.0f};
  float radius = -1.0f;

  bool empty() const { return radius < 0.0f; }
};

// The smallest sphere enclosing both (either may be empty).
BoundingSphere merge(const BoundingSphere& a, const BoundingSphere& b);

// A sphere around finite points: the centre of their bounding box and the largest
// distance to it; empty for no points.
BoundingSphere bounding_sphere(std::span<const glm::vec3> points);

class Camera {
 public:
  enum class Mode { orbit, planar };

  static Camera orbit();   // 3D, perspective, the default view above
  static Camera planar();  // 2D, orthographic

  Mode mode = Mode::orbit;
  glm::vec3 target{0.0f};      // orbit: the point orbited and looked at; planar: the view centre (x, y)
  float azimuth_deg = 0.0f;    // orbit
  float elevation_deg = 0.0f;  // orbit, kept within +-89.9
  float distance = 3.0f;       // orbit: eye to target
  float fov_y_deg = 40.0f;     // orbit: vertical field of view
  float half_height = 1.0f;    // planar: half the visible height, world units
  // The scene's extent; it places the near and far planes so depth keeps its precision.
  BoundingSphere scene{glm::vec3{0.0f}, 1.0f};

  // Interaction. Pixels are window pixels of `viewport`, y down as in window systems.
  void orbit_by(float d_azimuth_deg, float d_elevation_deg);
  void pan_by_pixels(glm::vec2 delta_px, const Viewport& viewport);  // the scene follows the cursor
  void zoom_by(float factor);                                        // > 1 zooms in

  // Frames `bounds` (centred, filling the smaller side of the viewport with a small
  // margin), keeping the view direction. Throws std::invalid_argument if bounds are empty
  // or not finite, or aspect is not positive.
  void fit(const BoundingSphere& bounds, float aspect);
  // Looks at the centre of `bounds` and takes them as the scene, keeping distance and zoom.
  void center_on(const BoundingSphere& bounds);

  glm::vec3 eye() const;  // orbit: the eye position; planar: a point above the plane
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  // Window coordinates of a world point: x right, y down from the viewport's top-left, in pixels,
  // and z the depth in [0, 1] (outside when behind the eye).
  glm::vec3 to_window(const glm::vec3& world, const Viewport& viewport) const;

  // Throws std::invalid_argument naming the first field that is not usable.
  void validate() const;
};

// JSON: {"mode": "orbit"|"planar", "target": [x,y,z], "azimuth_deg", "elevation_deg",
// "distance", "fov_y_deg", "half_height", "scene": {"center": [x,y,z], "radius"}}.
// Reading throws std::invalid_argument naming the missing or bad field.
void to_json(nlohmann::json& j, const Camera& camera);
void from_json(const nlohmann::json& j, Camera& camera);

}  // namespace amls
