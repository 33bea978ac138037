#pragma once
// Small triangle meshes for the mesh tests.
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <map>
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

// The box from `lo` with `cells[a]` lattice cells of length `step[a]` along
// axis a, its faces cut into two triangles per cell (outward,
// counter-clockwise seen from outside), sharing the vertices on the box's
// edges: a closed mesh whose vertex spacing a file carries without saying it.
inline TriangleMesh lattice_box_mesh(const Vec<3>& lo, const std::array<int, 3>& cells, const Vec<3>& step) {
  TriangleMesh m;
  std::map<std::array<int, 3>, std::uint32_t> index;
  const auto vertex = [&](const std::array<int, 3>& at) {
    const auto [it, added] = index.emplace(at, static_cast<std::uint32_t>(m.vertices.size()));
    if (added) m.vertices.push_back(lo + step.cwiseProduct(Vec<3>(at[0], at[1], at[2])));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    // (axis, u, v) right-handed: a cell's corners in (u, v) order wind counter-clockwise seen from +axis.
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const int side : {0, cells[axis]})
      for (int i = 0; i < cells[u]; ++i)
        for (int j = 0; j < cells[v]; ++j) {
          std::array<std::uint32_t, 4> corner{};
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> at{};
            at[axis] = side;
            at[u] = i + du[c];
            at[v] = j + dv[c];
            corner[c] = vertex(at);
          }
          if (side == 0) std::swap(corner[1], corner[3]);  // seen from -axis
          m.triangles.push_back({corner[0], corner[1], corner[2]});
          m.triangles.push_back({corner[0], corner[2], corner[3]});
        }
  }
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
