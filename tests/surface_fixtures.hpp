#pragma once
// Small builders shared by the tests: a ready AMLS surface from a point set.
#include "core/amls_surface.hpp"

namespace amls::test {

template <int D>
AmlsSurface<D> ready_surface(PointSet<D> points, const Grid<D>& grid, ThreadPool& pool,
                             AmlsParameters parameters = {}) {
  AmlsSurface<D> surface(grid, parameters);
  surface.set_points(std::move(points));
  surface.hash_points();
  surface.update_normals(pool);
  return surface;
}

// The distance from each point to its nearest other point.
template <int D>
std::vector<double> nearest_neighbour_distances(const std::vector<Vec<D>>& p) {
  std::vector<double> out(p.size(), 1e300);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j)
      if (i != j) out[i] = std::min(out[i], (p[i] - p[j]).norm());
  return out;
}

}  // namespace amls::test
