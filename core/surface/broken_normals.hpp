#pragma once
// The normals of a point set that disagree with those of the points beside
// them: a scan's broken normals, mended before F is fitted.
//
// F's fits pair each sample's normal with its neighbours' (the orientation
// filter keeps out of a fit the neighbours whose normal faces away), so one
// sample whose normal points inside a closed surface makes F change sign
// around it: a bubble of the wrong side, a hole in a mesh. One whose normal
// lies across the surface gets a pseudo-normal of either sign, and the rim
// search, which looks for gaps among the neighbours that face its way, marks
// rim samples on a closed surface there. CGAL's ball.ply has 96 normals of
// the first kind among 31,374; sphere_20k_normal.xyz, whose normals scatter by
// a median 17.6 degrees, 791 of the second among 21,000.
//
// The points beside a point are its neighbours within `radius` that lie
// within kBesideDegrees of its tangent plane (the same plane whichever way its
// normal points). Where there are at least kFewestBeside of them, the point's
// normal is broken when it points against (more than 180 - kBrokenDegrees
// from) the normals of kOpposedShare of them or more, and is turned over; or
// when their normals agree (their mean's length at least kAgreeing) and it
// lies more than kBrokenDegrees from their mean direction, and is replaced by
// that direction. The plane and the shares are what tell a broken normal from
// the other side of a thin part: a sheet's other side thicker than the
// spacing lies off the tangent plane, and one thinner than the spacing lies
// in it but is sampled about as densely as this side, so that the normals
// beside the point split into halves that neither reach kOpposedShare nor
// agree. At a sharp edge the other face's points lie off the plane, and
// where they do not (an edge sharper than 60 degrees) the two faces' normals
// split too.
//
// Broken normals are mended, and their neighbours tested again, until none is
// left or kMostRounds have passed. A cluster of broken normals is mended
// where it holds less than a fifth of the points beside each of its members;
// a patch as large as that is taken for a part of its own.
#include <cstddef>
#include <vector>

#include "core/math/vec.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

struct BrokenNormals {
  static constexpr double kBesideDegrees = 30.0;
  static constexpr double kOpposedShare = 0.8;
  static constexpr double kAgreeing = 0.6;
  static constexpr double kBrokenDegrees = 60.0;
  static constexpr int kFewestBeside = 4;
  static constexpr int kMostRounds = 8;

  std::vector<std::size_t> turned;    // normals turned over, in increasing order
  std::vector<std::size_t> replaced;  // normals replaced by their neighbours' mean direction, in increasing order
  int rounds = 0;                     // rounds that mended any
};

// Mends the broken normals of `normals` (unit, one a point of `positions`,
// positions finite). `radius` > 0, e.g. the support Delta. A normal both
// turned and later replaced counts as replaced.
template <int D>
BrokenNormals mend_broken_normals(const std::vector<Vec<D>>& positions, std::vector<Vec<D>>& normals, double radius,
                                  ThreadPool& pool);

extern template BrokenNormals mend_broken_normals<2>(const std::vector<Vec<2>>&, std::vector<Vec<2>>&, double,
                                                    ThreadPool&);
extern template BrokenNormals mend_broken_normals<3>(const std::vector<Vec<3>>&, std::vector<Vec<3>>&, double,
                                                    ThreadPool&);

}  // namespace amls
