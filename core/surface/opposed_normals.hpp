#pragma once
// The normals of a point set that point against those of the points beside
// them: a scan's broken normals, turned over before F is fitted.
//
// F's fits pair each sample's normal with its neighbours' (the orientation
// filter keeps out of a fit the neighbours whose normal faces away), so one
// sample whose normal points inside a closed surface makes F change sign
// around it: a bubble of the wrong side, a hole in a mesh, rim marks on a
// closed surface. CGAL's ball.ply has 96 such normals among 31,374.
//
// A point's normal is opposed when, of its neighbours within `radius` that
// lie beside it (within kBesideDegrees of its tangent plane, which is the same
// plane whichever way its normal points), at least kOpposedShare have a
// normal against its own, and there are at least
// kFewestBeside of them; a normal is against another when they lie more than
// kAgainstDegrees apart (the rim search's kRimFacing), not merely at an obtuse
// angle: a noisy normal near the tangent plane, at 95 degrees from its
// neighbours', is no better turned over. The plane is what tells a broken normal from the
// other side of a thin part: a sheet's other side thicker than the spacing
// lies off the tangent plane and does not vote, and one thinner than the
// spacing votes but is at most about half of the neighbours (it is sampled as
// densely as this side), well under kOpposedShare. Sharp edges vote with
// normals near perpendicular, which split both ways.
//
// Opposed normals are turned, and their neighbours tested again, until none is
// left or kMostRounds have passed. A cluster of broken normals is turned
// where it holds less than 1 - kOpposedShare of the points beside each of its
// members; a patch as large as that is taken for a part of its own.
#include <cstddef>
#include <vector>

#include "core/math/vec.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct OpposedNormals {
  static constexpr double kBesideDegrees = 30.0;
  static constexpr double kAgainstDegrees = 120.0;
  static constexpr double kOpposedShare = 0.8;
  static constexpr int kFewestBeside = 4;
  static constexpr int kMostRounds = 8;

  std::vector<std::size_t> turned;  // the points whose normal was turned, in increasing order
  int rounds = 0;                   // rounds that turned any
};

// Turns the opposed normals of `normals` (unit, one a point of `positions`,
// positions finite). `radius` > 0, e.g. the support Delta.
template <int D>
OpposedNormals turn_opposed_normals(const std::vector<Vec<D>>& positions, std::vector<Vec<D>>& normals, double radius,
                                    ThreadPool& pool);

extern template OpposedNormals turn_opposed_normals<2>(const std::vector<Vec<2>>&, std::vector<Vec<2>>&, double,
                                                      ThreadPool&);
extern template OpposedNormals turn_opposed_normals<3>(const std::vector<Vec<3>>&, std::vector<Vec<3>>&, double,
                                                      ThreadPool&);

}  // namespace amls
