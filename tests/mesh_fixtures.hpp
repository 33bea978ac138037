#pragma once
// Small triangle meshes for the mesh tests.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/io/mesh_io.hpp"

namespace amls::test {

// The axis-aligned box from `lo` to `hi` as 12 triangles, counter-clockwise
// seen from outside unless `inward`.
inline TriangleMesh box_mesh(const Vec<3>& lo, const Vec<3>& hi, bool inward = false) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  if (inward)
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// The volume a closed triangle mesh encloses, by the divergence theorem:
// positive when its triangles face outwards.
inline double enclosed_volume(const std::vector<Vec<3>>& vertices,
                              const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  double six_volume = 0.0;
  for (const auto& t : triangles) six_volume += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]]));
  return six_volume / 6.0;
}

}  // namespace amls::test
