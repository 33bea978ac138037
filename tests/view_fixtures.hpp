#pragma once
// The views the editor's screen-space tests look through: an 800x600
// viewport framing the unit sphere, planar (2D) or orbiting (3D).
#include <glm/glm.hpp>

#include "render/camera.hpp"

namespace amls::test {

inline const Viewport kViewport{0, 0, 800, 600};

inline Camera planar_camera() {
  Camera c = Camera::planar();
  c.fit(BoundingSphere{glm::vec3(0.0f), 1.0f}, kViewport.aspect());
  return c;
}

// Azimuth 0: the eye on +z, +y up.
inline Camera orbit_camera(float azimuth = 0.0f) {
  Camera c = Camera::orbit();
  c.azimuth_deg = azimuth;
  c.fit(BoundingSphere{glm::vec3(0.0f), 1.0f}, kViewport.aspect());
  return c;
}

// Where p is on screen, in the viewport's pixels.
inline glm::vec2 window_of(const Camera& c, const glm::vec3& p) { return glm::vec2(c.to_window(p, kViewport)); }

}  // namespace amls::test
