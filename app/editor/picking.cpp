#include "app/editor/picking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amls::editor {

namespace {

// The view direction (from the eye into the scene).
glm::vec3 forward(const Camera& camera) {
  if (camera.mode == Camera::Mode::planar) return {0.0f, 0.0f, -1.0f};
  return glm::normalize(camera.target - camera.eye());
}

float squared(glm::vec2 v) { return glm::dot(v, v); }

}  // namespace

Ray pixel_ray(const Camera& camera, const Viewport& viewport, glm::vec2 pixel) {
  const glm::mat4 inverse = glm::inverse(camera.projection(viewport.aspect()) * camera.view());
  const float x = 2.0f * pixel.x / static_cast<float>(viewport.width) - 1.0f;
  const float y = 1.0f - 2.0f * pixel.y / static_cast<float>(viewport.height);
  const glm::vec4 near_point = inverse * glm::vec4(x, y, -1.0f, 1.0f);
  const glm::vec4 far_point = inverse * glm::vec4(x, y, 1.0f, 1.0f);
  const glm::vec3 a = glm::vec3(near_point) / near_point.w;
  const glm::vec3 b = glm::vec3(far_point) / far_point.w;
  return Ray{a, glm::normalize(b - a)};
}

namespace {

// A point near the cursor: its squared distance on screen and its depth.
struct Candidate {
  std::size_t index;
  float screen2;
  float depth;
};

float depth_of(const Camera& camera, const glm::vec3& p) {
  return camera.mode == Camera::Mode::orbit ? glm::length(p - camera.eye()) : -p.z;
}

// Of the candidates, the one pick_point chooses.
std::optional<std::size_t> choose(std::span<const Candidate> candidates, std::span<const glm::vec3> positions,
                                  std::span<const glm::vec3> normals, const Camera& camera) {
  if (candidates.empty()) return std::nullopt;
  const glm::vec3 eye = camera.eye();
  auto facing = [&](std::size_t i) {
    if (camera.mode != Camera::Mode::orbit || normals.size() != positions.size()) return true;
    return glm::dot(normals[i], eye - positions[i]) > 0.0f;
  };
  // First: the nearest eye distance among front-facing candidates (any candidate if none faces the viewer).
  bool any_facing = false;
  for (const Candidate& c : candidates) any_facing = any_facing || facing(c.index);
  float nearest_depth = std::numeric_limits<float>::infinity(), farthest_depth = -nearest_depth;
  for (const Candidate& c : candidates) {
    if (any_facing && !facing(c.index)) continue;
    nearest_depth = std::min(nearest_depth, c.depth);
    farthest_depth = std::max(farthest_depth, c.depth);
  }
  // Candidates within a slab behind the nearest one (a tenth of their depth spread, so a
  // sheet seen edge-on still counts as one): of those, the nearest on screen.
  const float slab = nearest_depth + 0.1f * (farthest_depth - nearest_depth) + 1e-6f;
  std::optional<std::size_t> best;
  float best2 = std::numeric_limits<float>::infinity();
  for (const Candidate& c : candidates) {
    if ((any_facing && !facing(c.index)) || c.depth > slab) continue;
    // Ties go to the lower index, so that the choice does not depend on the candidates' order.
    if (c.screen2 < best2 || (c.screen2 == best2 && c.index < *best)) {
      best2 = c.screen2;
      best = c.index;
    }
  }
  return best;
}

}  // namespace

std::optional<std::size_t> pick_point(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                      const Camera& camera, const Viewport& viewport, glm::vec2 pixel, float radius_px,
                                      float world_radius) {
  std::vector<Candidate> candidates;
  const float r2 = radius_px * radius_px;
  const glm::mat4 view = camera.view();
  const glm::vec3 right = world_radius * glm::vec3(view[0][0], view[1][0], view[2][0]);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 w = camera.to_window(positions[i], viewport);
    if (w.z < 0.0f || w.z > 1.0f) continue;
    const float d2 = squared(glm::vec2(w) - pixel);
    if (d2 > r2 && (world_radius <= 0.0f ||
                    d2 > squared(glm::vec2(camera.to_window(positions[i] + right, viewport)) - glm::vec2(w))))
      continue;
    candidates.push_back({i, d2, depth_of(camera, positions[i])});
  }
  return choose(candidates, positions, normals, camera);
}

std::optional<std::size_t> pick_point(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera, glm::vec2 pixel,
                                      float radius_px) {
  std::vector<Candidate> candidates;
  const float r2 = radius_px * radius_px;
  grid.for_each_in(ScreenGrid::Box{pixel - radius_px, pixel + radius_px}, [&](std::size_t i) {
    const glm::vec3& w = grid.window(i);
    if (w.z < 0.0f || w.z > 1.0f) return;
    const float d2 = squared(glm::vec2(w) - pixel);
    if (d2 <= r2) candidates.push_back({i, d2, depth_of(camera, positions[i])});
  });
  return choose(candidates, positions, normals, camera);
}

std::optional<std::size_t> pick_handle(std::span<const glm::vec3> handles, const Camera& camera,
                                       const Viewport& viewport, glm::vec2 pixel, float radius_px) {
  std::optional<std::size_t> best;
  float best2 = radius_px * radius_px;
  for (std::size_t i = 0; i < handles.size(); ++i) {
    const glm::vec3 w = camera.to_window(handles[i], viewport);
    if (w.z < 0.0f || w.z > 1.0f) continue;
    const float d2 = squared(glm::vec2(w) - pixel);
    if (d2 <= best2) {
      best2 = d2;
      best = i;
    }
  }
  return best;
}

std::optional<glm::vec3> plane_point(const Camera& camera, const Viewport& viewport, glm::vec2 pixel,
                                     const glm::vec3& anchor) {
  const Ray ray = pixel_ray(camera, viewport, pixel);
  const glm::vec3 normal = forward(camera);
  const float along = glm::dot(ray.direction, normal);
  if (std::abs(along) < 1e-6f) return std::nullopt;
  const float t = glm::dot(anchor - ray.origin, normal) / along;
  glm::vec3 p = ray.origin + t * ray.direction;
  if (camera.mode == Camera::Mode::planar) p.z = anchor.z;  // exactly in the plane, whatever the rounding
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
  return p;
}

std::optional<glm::vec3> drag_position(const Camera& camera, const Viewport& viewport, glm::vec2 pixel,
                                       const glm::vec3& start, const glm::vec3& grab, AxisLock lock) {
  const std::optional<glm::vec3> p = plane_point(camera, viewport, pixel, start);
  if (!p) return std::nullopt;
  const glm::vec3 free = *p + grab;
  if (lock == AxisLock::none) return free;
  const int axis = lock == AxisLock::x ? 0 : lock == AxisLock::y ? 1 : 2;
  glm::vec3 locked = start;
  locked[axis] = free[axis];
  return locked;
}

}  // namespace amls::editor
