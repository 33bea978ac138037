#pragma once
// Exact sample sets of simple shapes with outward unit normals.
//
// The samplers that take a `spacing` aim at a nearest-neighbour distance of
// about `spacing` between the points (within some 25 %), evenly spread.
#include <cstddef>

#include "core/geometry/point_set.hpp"

namespace amls {

// `count` points evenly spaced on a circle (2D).
PointSet<2> sample_circle(const Vec<2>& center, double radius, std::size_t count);

// `count` points on a sphere (3D), evenly spread by the Fibonacci lattice.
PointSet<3> sample_sphere(const Vec<3>& center, double radius, std::size_t count);

// The point counts that give a nearest-neighbour distance of about `spacing`:
// 2 pi r / spacing on a circle (at least 3); on a sphere the count of a
// hexagonal lattice of that spacing over its area (at least 4).
std::size_t circle_points_for_spacing(double radius, double spacing);
std::size_t sphere_points_for_spacing(double radius, double spacing);

// An ellipse with the given semi-axes along x and y, evenly spaced in arc length.
PointSet<2> sample_ellipse(const Vec<2>& center, const Vec<2>& semi_axes, double spacing);

// A torus about the z axis: the circle of radius `minor_radius` in a plane
// through the axis, swept at `major_radius` from it (major > minor > 0).
// Rings of constant minor angle, staggered.
PointSet<3> sample_torus(const Vec<3>& center, double major_radius, double minor_radius, double spacing);

// The box [center - half_extents, center + half_extents] with its edges (and,
// in 3D, corners) rounded to `radius` (0 <= radius <= every half extent; 0
// gives a sharp box): the points at distance `radius` from the inner box of
// half extents half_extents - radius. Flat faces and rounded edges are sampled
// on cell-centred grids, corners by the Fibonacci lattice.
PointSet<2> sample_rounded_box(const Vec<2>& center, const Vec<2>& half_extents, double radius, double spacing);
PointSet<3> sample_rounded_box(const Vec<3>& center, const Vec<3>& half_extents, double radius, double spacing);

}  // namespace amls
