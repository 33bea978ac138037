#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace amls {

namespace {

constexpr float kMaxElevationDeg = 89.9f;
constexpr float kFitMargin = 1.05f;  // framed bounds leave 5% of the half-size free

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The unit vector from the target to the eye.
glm::vec3 orbit_direction(float azimuth_deg, float elevation_deg) {
  const float az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
  return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

// Margin added around the scene when placing the near and far planes.
float depth_reach(const BoundingSphere& scene) { return std::max(scene.radius, 0.0f) * 1.01f + 1e-6f; }

}  // namespace

BoundingSphere merge(const BoundingSphere& a, const BoundingSphere& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const glm::vec3 d = b.center - a.center;
  const float dist = glm::length(d);
  if (dist + b.radius <= a.radius) return a;
  if (dist + a.radius <= b.radius) return b;
  const float radius = 0.5f * (dist + a.radius + b.radius);
  return {a.center + d * ((radius - a.radius) / dist), radius};
}

BoundingSphere bounding_sphere(std::span<const glm::vec3> points) {
  if (points.empty()) return {};
  glm::vec3 lo = points.front(), hi = points.front();
  for (const glm::vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 center = 0.5f * (lo + hi);
  float r2 = 0.0f;
  for (const glm::vec3& p : points) r2 = std::max(r2, glm::dot(p - center, p - center));
  return {center, std::sqrt(r2)};
}

Camera Camera::orbit() { return Camera{}; }

Camera Camera::planar() {
  Camera c;
  c.mode = Mode::planar;
  return c;
}

void Camera::orbit_by(float d_azimuth_deg, float d_elevation_deg) {
  azimuth_deg = std::remainder(azimuth_deg + d_azimuth_deg, 360.0f);
  elevation_deg = std::clamp(elevation_deg + d_elevation_deg, -kMaxElevationDeg, kMaxElevationDeg);
}

void Camera::pan_by_pixels(glm::vec2 delta_px, const Viewport& viewport) {
  if (viewport.height <= 0) return;
  if (mode == Mode::planar) {
    const float world_per_px = 2.0f * half_height / static_cast<float>(viewport.height);
    target.x -= delta_px.x * world_per_px;
    target.y += delta_px.y * world_per_px;
    return;
  }
  const float world_per_px =
      2.0f * distance * std::tan(0.5f * glm::radians(fov_y_deg)) / static_cast<float>(viewport.height);
  const glm::mat4 v = view();
  const glm::vec3 right{v[0][0], v[1][0], v[2][0]};
  const glm::vec3 up{v[0][1], v[1][1], v[2][1]};
  target += world_per_px * (up * delta_px.y - right * delta_px.x);
}

void Camera::zoom_by(float factor) {
  if (!(factor > 0.0f) || !std::isfinite(factor)) return;
  if (mode == Mode::planar)
    half_height = std::max(half_height / factor, 1e-12f);
  else
    distance = std::max(distance / factor, 1e-12f);
}

void Camera::center_on(const BoundingSphere& bounds) {
  if (bounds.empty()) throw std::invalid_argument("cannot frame an empty scene");
  if (!finite(bounds.center) || !std::isfinite(bounds.radius))
    throw std::invalid_argument("cannot frame a scene whose bounds are not finite");
  scene = {bounds.center, bounds.radius > 0.0f ? bounds.radius : 1.0f};
  target = bounds.center;
}

void Camera::fit(const BoundingSphere& bounds, float aspect) {
  if (!(aspect > 0.0f) || !std::isfinite(aspect))
    throw std::invalid_argument("cannot fit the camera to a viewport of aspect ratio " + std::to_string(aspect));
  center_on(bounds);
  const float radius = scene.radius;
  if (mode == Mode::planar) {
    half_height = kFitMargin * radius * std::max(1.0f, 1.0f / aspect);
    return;
  }
  const float tan_half_y = std::tan(0.5f * glm::radians(fov_y_deg));
  const float half_angle = std::atan(std::min(tan_half_y, tan_half_y * aspect));
  distance = kFitMargin * radius / std::sin(half_angle);
}

glm::vec3 Camera::eye() const {
  if (mode == Mode::planar) return {target.x, target.y, scene.center.z + depth_reach(scene)};
  return target + distance * orbit_direction(azimuth_deg, elevation_deg);
}

glm::mat4 Camera::view() const {
  if (mode == Mode::planar) return glm::translate(glm::mat4(1.0f), glm::vec3(-target.x, -target.y, 0.0f));
  return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projection(float aspect) const {
  const float reach = depth_reach(scene);
  if (mode == Mode::planar) {
    const float half_width = half_height * aspect;
    // Eye-space z equals world z here; the scene spans [center.z - reach, center.z + reach].
    return glm::ortho(-half_width, half_width, -half_height, half_height, -(scene.center.z + reach),
                      -(scene.center.z - reach));
  }
  const float d = glm::length(eye() - scene.center);
  const float far_plane = d + reach;
  // Keep near/far within 2^12 so that a 24-bit depth buffer still separates overlapping splats.
  const float near_plane = std::max(d - reach, far_plane / 4096.0f);
  return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
}

glm::vec3 Camera::to_window(const glm::vec3& world, const Viewport& viewport) const {
  const glm::vec4 clip = projection(viewport.aspect()) * view() * glm::vec4(world, 1.0f);
  if (!(clip.w > 0.0f)) return {0.0f, 0.0f, 2.0f};
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * static_cast<float>(viewport.width),
          (0.5f - ndc.y * 0.5f) * static_cast<float>(viewport.height), ndc.z * 0.5f + 0.5f};
}

void Camera::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("camera: ") + what);
  };
  require(finite(target), "target must be finite");
  require(std::isfinite(azimuth_deg), "azimuth_deg must be finite");
  require(std::isfinite(elevation_deg) && std::abs(elevation_deg) <= kMaxElevationDeg,
          "elevation_deg must be within [-89.9, 89.9]");
  require(distance > 0.0f && std::isfinite(distance), "distance must be positive and finite");
  require(fov_y_deg > 0.0f && fov_y_deg < 180.0f, "fov_y_deg must be in (0, 180)");
  require(half_height > 0.0f && std::isfinite(half_height), "half_height must be positive and finite");
  require(finite(scene.center) && std::isfinite(scene.radius) && scene.radius > 0.0f,
          "scene must have a finite centre and a positive radius");
}

void to_json(nlohmann::json& j, const Camera& c) {
  auto vec = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  j = nlohmann::json{{"mode", c.mode == Camera::Mode::planar ? "planar" : "orbit"},
                     {"target", vec(c.target)},
                     {"azimuth_deg", c.azimuth_deg},
                     {"elevation_deg", c.elevation_deg},
                     {"distance", c.distance},
                     {"fov_y_deg", c.fov_y_deg},
                     {"half_height", c.half_height},
                     {"scene", {{"center", vec(c.scene.center)}, {"radius", c.scene.radius}}}};
}

void from_json(const nlohmann::json& j, Camera& c) {
  auto fail = [](const std::string& what) -> void { throw std::invalid_argument("camera JSON: " + what); };
  if (!j.is_object()) fail("expected an object");
  auto number = [&](const nlohmann::json& parent, const char* key, float& out) {
    if (!parent.contains(key)) return;  // absent fields keep their defaults
    if (!parent[key].is_number()) fail(std::string("'") + key + "' must be a number");
    out = parent[key].get<float>();
  };
  auto vector = [&](const nlohmann::json& parent, const char* key, glm::vec3& out) {
    if (!parent.contains(key)) return;
    const nlohmann::json& a = parent[key];
    if (!a.is_array() || a.size() != 3 || !a[0].is_number() || !a[1].is_number() || !a[2].is_number())
      fail(std::string("'") + key + "' must be an array of 3 numbers");
    out = {a[0].get<float>(), a[1].get<float>(), a[2].get<float>()};
  };
  if (!j.contains("mode") || !j["mode"].is_string()) fail("'mode' must be \"orbit\" or \"planar\"");
  const std::string mode = j["mode"].get<std::string>();
  if (mode != "orbit" && mode != "planar") fail("'mode' must be \"orbit\" or \"planar\", got \"" + mode + "\"");
  Camera out = mode == "planar" ? Camera::planar() : Camera::orbit();
  vector(j, "target", out.target);
  number(j, "azimuth_deg", out.azimuth_deg);
  number(j, "elevation_deg", out.elevation_deg);
  number(j, "distance", out.distance);
  number(j, "fov_y_deg", out.fov_y_deg);
  number(j, "half_height", out.half_height);
  if (j.contains("scene")) {
    if (!j["scene"].is_object()) fail("'scene' must be an object");
    vector(j["scene"], "center", out.scene.center);
    number(j["scene"], "radius", out.scene.radius);
  }
  out.validate();
  c = out;
}

}  // namespace amls
