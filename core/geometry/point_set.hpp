#pragma once
// A point set with one oriented unit normal per point, structure of arrays,
// and the marks of the points a resample carried as an open surface's rim.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
struct PointSet {
  std::vector<Vec<D>> positions;
  std::vector<Vec<D>> normals;
  // Empty (no point is known to be on a rim) or one per point: 1 where a
  // resample carried the point as a rim point (core/resample/rim_carrying.hpp).
  // The next resample keeps such a point on the rim unless its neighbours
  // come to surround it, instead of deciding anew whether it is one.
  std::vector<std::uint8_t> rim = {};

  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }
  bool on_rim(std::size_t i) const { return !rim.empty() && rim[i] != 0; }

  void clear() {
    positions.clear();
    normals.clear();
    rim.clear();
  }
  void reserve(std::size_t n) {
    positions.reserve(n);
    normals.reserve(n);
  }
  // A rim mark makes the marks one per point from then on.
  void add(const Vec<D>& position, const Vec<D>& normal, bool on_the_rim = false) {
    if (on_the_rim && rim.empty()) rim.assign(positions.size(), 0);
    positions.push_back(position);
    normals.push_back(normal);
    if (!rim.empty()) rim.push_back(on_the_rim ? 1 : 0);
  }
};

}  // namespace amls
