#pragma once
// A point set with one oriented unit normal per point, structure of arrays.
#include <cstddef>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
struct PointSet {
  std::vector<Vec<D>> positions;
  std::vector<Vec<D>> normals;

  std::size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }

  void clear() {
    positions.clear();
    normals.clear();
  }
  void reserve(std::size_t n) {
    positions.reserve(n);
    normals.reserve(n);
  }
  void add(const Vec<D>& position, const Vec<D>& normal) {
    positions.push_back(position);
    normals.push_back(normal);
  }
};

}  // namespace amls
