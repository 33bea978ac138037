#include "app/editor/lasso.hpp"

#include <algorithm>

namespace amls::editor {

namespace {

// In 3D, whether a point with this normal faces the eye (a planar view sees everything).
bool faces_eye(const Camera& camera, std::span<const glm::vec3> normals, std::span<const glm::vec3> positions,
               std::size_t i) {
  if (normals.empty() || camera.mode == Camera::Mode::planar) return true;
  return glm::dot(normals[i], camera.eye() - positions[i]) > 0.0f;
}

}  // namespace

bool inside_polygon(std::span<const glm::vec2> polygon, glm::vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

std::vector<std::size_t> lasso_select(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera,
                                      std::span<const glm::vec2> polygon) {
  std::vector<std::size_t> out;
  if (polygon.size() < 3) return out;
  glm::vec2 low = polygon[0], high = low;
  for (const glm::vec2& p : polygon) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  grid.for_each_in(ScreenGrid::Box{low, high}, [&](std::size_t i) {
    const glm::vec3& w = grid.window(i);
    const glm::vec2 p(w.x, w.y);
    if (w.z < 0.0f || w.z > 1.0f || glm::any(glm::lessThan(p, low)) || glm::any(glm::greaterThan(p, high))) return;
    if (inside_polygon(polygon, p) && faces_eye(camera, normals, positions, i)) out.push_back(i);
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::size_t> brush_select(const ScreenGrid& grid, std::span<const glm::vec3> positions,
                                      std::span<const glm::vec3> normals, const Camera& camera, const glm::vec3& centre,
                                      float radius) {
  std::vector<std::size_t> out;
  grid.for_each_in(grid.sphere_box(centre, radius), [&](std::size_t i) {
    if (glm::distance(positions[i], centre) <= radius && faces_eye(camera, normals, positions, i)) out.push_back(i);
  });
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace amls::editor
