#include "core/io/mesh_inside.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

namespace amls {

double winding_number(const TriangleMesh& mesh, const Vec<3>& x) {
  double solid_angle = 0.0;
  for (const auto& t : mesh.triangles) {
    // Van Oosterom and Strackee's formula for the solid angle of a triangle.
    const Vec<3> a = mesh.vertices[t[0]] - x, b = mesh.vertices[t[1]] - x, c = mesh.vertices[t[2]] - x;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * std::numbers::pi);
}

bool closed_and_consistently_wound(const TriangleMesh& mesh) {
  // Each directed edge once, and its reverse as often as it.
  std::unordered_map<std::uint64_t, int> directed;
  auto key = [](std::uint32_t from, std::uint32_t to) { return (static_cast<std::uint64_t>(from) << 32) | to; };
  for (const auto& t : mesh.triangles)
    for (std::size_t k = 0; k < 3; ++k)
      if (++directed[key(t[k], t[(k + 1) % 3])] > 1) return false;
  for (const auto& [edge, count] : directed) {
    const auto from = static_cast<std::uint32_t>(edge >> 32), to = static_cast<std::uint32_t>(edge);
    if (!directed.contains(key(to, from))) return false;
  }
  return !mesh.triangles.empty();
}

}  // namespace amls
