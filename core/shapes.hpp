#pragma once
// Exact sample sets of simple shapes with outward unit normals.
#include <cstddef>

#include "core/point_set.hpp"

namespace amls {

// `count` points evenly spaced on a circle (2D).
PointSet<2> sample_circle(const Vec<2>& center, double radius, std::size_t count);

// `count` points on a sphere (3D), evenly spread by the Fibonacci lattice.
PointSet<3> sample_sphere(const Vec<3>& center, double radius, std::size_t count);

}  // namespace amls
