#pragma once
// Small triangle meshes for the mesh tests.
#include <cstdint>
#include <utility>

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

}  // namespace amls::test
