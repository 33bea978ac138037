#pragma once
// Properties that both resamplers (the grid walk and the ray-tracing baseline)
// must have, checked alike: the same inputs, the same tolerances.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/surface/metrics.hpp"
#include "core/geometry/shapes.hpp"
#include "surface_fixtures.hpp"

namespace amls::test {

// The test circle: r = 0.15 at (0.5, 0.75), 150 points, on the 128^2 grid.
inline const Vec<2> kCircleCenter(0.5, 0.75);
inline constexpr double kCircleRadius = 0.15;
inline AmlsSurface<2> circle_surface(ThreadPool& pool) {
  return ready_surface(sample_circle(kCircleCenter, kCircleRadius, 150), Grid<2>::unit(128), pool);
}

// The test sphere: r = 0.15 at (0.35, 0.35, 0.35), 3000 points, on the 64^3 grid.
inline const Vec<3> kSphereCenter(0.35, 0.35, 0.35);
inline constexpr double kSphereRadius = 0.15;
inline AmlsSurface<3> sphere_surface(ThreadPool& pool) {
  return ready_surface(sample_sphere(kSphereCenter, kSphereRadius, 3000), Grid<3>::unit(64), pool);
}

// Every new point lies on F = 0 and on the circle (the AMLS function reproduces
// it exactly), with the outward normal, and no gap between angular neighbours
// is wider than 2 h (clusters merged within h/2 can leave h/2 + the widest gap
// between crossings + h/2).
inline void check_resampled_circle(const AmlsSurface<2>& surface, const PointSet<2>& out) {
  const double h = surface.grid().spacing();
  REQUIRE(out.size() > 100);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Evaluation<2> e = surface.evaluate(out.positions[i]);
    REQUIRE(e.defined);
    CHECK(std::abs(e.value) < 1e-12);
    CHECK(std::abs((out.positions[i] - kCircleCenter).norm() - kCircleRadius) < 1e-10);
    CHECK(out.normals[i].dot((out.positions[i] - kCircleCenter).normalized()) > 0.999999);
  }
  CHECK(widest_circle_gap(out.positions, kCircleCenter, kCircleRadius) < 2.0 * h);
}

// Every new point lies on the sphere, and every place on the sphere lies within
// 1.25 h of a new point (no hole).
inline void check_resampled_sphere(const AmlsSurface<3>& surface, const PointSet<3>& out) {
  REQUIRE(out.size() > 800);
  double worst = 0.0;
  for (const Vec<3>& p : out.positions) worst = std::max(worst, std::abs((p - kSphereCenter).norm() - kSphereRadius));
  CHECK(worst < 1e-9);
  const PointSet<3> probes = sample_sphere(kSphereCenter, kSphereRadius, 20000);
  CHECK(nearest_distance_stats<3>(probes.positions, out.positions, surface.grid().spacing()).max < 1.25);
}

// The line y = 0.5 on a grid line of the 16-cell grid: F is exactly 0 at its vertices.
inline AmlsSurface<2> line_through_vertices(ThreadPool& pool) {
  PointSet<2> line;
  for (int i = 0; i <= 40; ++i) line.add(Vec<2>(0.25 + 0.0125 * i, 0.5), Vec<2>(0, 1));
  return ready_surface(std::move(line), Grid<2>::unit(16), pool);
}

// Every new point lies on the line at a vertex, at most one per vertex.
inline void check_one_point_per_vertex(const PointSet<2>& out, double h) {
  REQUIRE(!out.empty());
  std::vector<double> xs;
  for (const auto& q : out.positions) {
    CHECK(q.y() == 0.5);
    const double k = q.x() / h;
    CHECK(k == std::round(k));  // on a vertex
    xs.push_back(q.x());
  }
  std::sort(xs.begin(), xs.end());
  CHECK(std::adjacent_find(xs.begin(), xs.end()) == xs.end());
}

}  // namespace amls::test
