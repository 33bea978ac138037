#pragma once
// Small builders shared by the tests: a ready AMLS surface from a point set,
// sampled shapes and their measures.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/shapes.hpp"
#include "core/surface/amls_surface.hpp"

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

// Points about `spacing` apart on the cylinder of `radius` around the z axis
// through `center`, from z = center.z - half_length to + half_length, with
// outward normals.
inline PointSet<3> sample_cylinder(const Vec<3>& center, double radius, double half_length, double spacing) {
  PointSet<3> out;
  const int around = static_cast<int>(std::round(2.0 * std::numbers::pi * radius / spacing));
  const int along = static_cast<int>(std::round(half_length / spacing));
  for (int k = -along; k <= along; ++k)
    for (int j = 0; j < around; ++j) {
      // Rings alternately turned by half a step, as a surface's samples would be.
      const double angle = 2.0 * std::numbers::pi * (j + 0.5 * (k & 1)) / around;
      const Vec<3> normal(std::cos(angle), std::sin(angle), 0.0);
      out.add(center + radius * normal + Vec<3>(0.0, 0.0, k * spacing), normal);
    }
  return out;
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

// The widest gap between angularly consecutive points about `center`, as arc
// length on the circle of `radius` (the whole circle for fewer than 2 points).
inline double widest_circle_gap(const std::vector<Vec<2>>& p, const Vec<2>& center, double radius) {
  std::vector<double> angles;
  for (const Vec<2>& q : p) angles.push_back(std::atan2(q.y() - center.y(), q.x() - center.x()));
  std::sort(angles.begin(), angles.end());
  if (angles.size() < 2) return 2.0 * std::numbers::pi * radius;
  double widest = angles.front() + 2.0 * std::numbers::pi - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) widest = std::max(widest, angles[i] - angles[i - 1]);
  return widest * radius;
}

// A unit sphere sampled `dense` points' worth on its upper half and 4 x more
// sparsely (16 x fewer points) on its lower half.
inline PointSet<3> half_sparse_sphere(std::size_t dense) {
  PointSet<3> points;
  const PointSet<3> fine = sample_sphere(Vec<3>::Zero(), 1.0, dense);
  const PointSet<3> coarse = sample_sphere(Vec<3>::Zero(), 1.0, dense / 16);
  for (std::size_t i = 0; i < fine.size(); ++i)
    if (fine.positions[i].z() > 0.0) points.add(fine.positions[i], fine.normals[i]);
  for (std::size_t i = 0; i < coarse.size(); ++i)
    if (coarse.positions[i].z() <= 0.0) points.add(coarse.positions[i], coarse.normals[i]);
  return points;
}

// How many of `probes` (points of a surface) have no output point within
// `reach`: holes.
inline std::size_t probes_in_holes(const std::vector<Vec<3>>& output, const std::vector<Vec<3>>& probes,
                                   double reach) {
  KdTree<3> tree;
  tree.build(output);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  std::size_t holes = 0;
  for (const Vec<3>& p : probes) {
    tree.nearest(p, 1, ids, squared);
    holes += squared.front() > reach * reach ? 1 : 0;
  }
  return holes;
}

}  // namespace amls::test
