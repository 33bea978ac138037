#pragma once
// Oriented normals for a point set that has none (input shapes from files).
//
// Each point's direction is the normal of its Pratt fit (the same algebraic
// sphere fit as the AMLS surface's Step 1, core/surface/pratt_fit.hpp) over its
// neighbours within `radius`, widened up to 8 times where too few are found;
// where even that fails, the direction of least spread of the neighbours.
// Orientation follows Hoppe et al., "Surface reconstruction from unorganized
// points" (SIGGRAPH 1992): over the graph joining each point to its k nearest
// neighbours, a minimum spanning tree under the weights 1 - |n_i . n_j| is
// grown from a seed whose orientation is known - the point with the largest
// last coordinate (z, or y in 2D), whose outward normal points up - and each
// point takes the sign that agrees with its parent. Each connected part of the
// graph is seeded on its own. Then each part takes the side away from its
// centroid, where its normals lean clearly one way (the mean of n . (p - c) at
// least 2 % of the mean |p - c|): outward for a closed surface, the convex side
// of an open one (a bowl's, whose highest points are on its rim, where "up"
// says little); a flat part keeps "up".
#include <cstddef>
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct NormalEstimation {
  std::size_t points = 0;
  std::size_t failed_fits = 0;      // Pratt fit failed at every radius: least-spread direction used
  std::size_t widened = 0;          // needed a radius wider than the one given
  std::size_t components = 0;       // connected parts of the neighbour graph
  std::size_t ambiguous_edges = 0;  // tree edges whose normals are more than ~72 degrees apart
  std::size_t first_ambiguous = 0; // a point at one of them (valid if ambiguous_edges > 0)
  std::size_t turned_parts = 0;     // parts turned over to lean away from their centroids
  // What the user should hear about: separate parts, ambiguous edges, failed fits.
  std::vector<std::string> warnings;
};

// Replaces points.normals with estimated, oriented unit normals (any normals
// present are ignored). Throws std::invalid_argument for fewer than D + 1
// points, a non-finite position or a radius that is not positive.
template <int D>
NormalEstimation estimate_normals(PointSet<D>& points, double radius, ThreadPool& pool);

extern template NormalEstimation estimate_normals<2>(PointSet<2>&, double, ThreadPool&);
extern template NormalEstimation estimate_normals<3>(PointSet<3>&, double, ThreadPool&);

}  // namespace amls
