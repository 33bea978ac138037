#pragma once
// How well a resampled point set covers the input it came from, both ways
// (docs/real-data.md, "Coverage"):
// - an input point p is covered when an output point lies within
//   kCoverageReach x local(p), where local(p) = max(h, p's own spacing) and p's
//   own spacing is its distance to its kSpacingNeighbours-th nearest input
//   neighbour / kSpacingNeighbourDivisor (the rule that chooses h, applied at p);
// - an output point is on the input when its nearest input point p lies within
//   kCoverageReach x local(p).
// A hole in the output leaves the input points around it uncovered; a spurious
// sheet puts output points off the input. Both measures look at the input's
// resolution: an output far finer than the input (--spacing well below its
// spacing) can come near every input point and still be torn between them.
// So the output is also measured on its own:
// - an output point is in a gap when its output neighbours within
//   kGapReach x h do not surround it (core/resample/resample_policy.hpp,
//   unsurrounded_points: one on each side in 2D, no empty sector of 150
//   degrees in 3D). The rims of holes are, and so are the rims of an open
//   scan, which kMostOutputInGaps leaves room for.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/math/vec.hpp"

namespace amls {

inline constexpr double kCoverageReach = 2.0;
// Below these fractions a resampling has clearly lost part of the input (or
// added a surface that is not there); `amls resample` then fails.
inline constexpr double kLeastInputCovered = 0.99;
inline constexpr double kLeastOutputOnInput = 0.95;
// A closed output right after resampling is surrounded within 2.2 h at every
// point (ResamplePolicy::max_gap); beyond 2.5 h it is torn. Real files leave
// some of their output in gaps: up to 8.2 % on CGAL's building scan, whose
// rims are long, at most 0.01 % on its meshes (docs/real-data.md); a torn
// output most of it (80 % in tests/test_point_set_resampling.cpp), the radar
// scan with one Delta 21.5 %.
inline constexpr double kGapReach = 2.5;
inline constexpr double kMostOutputInGaps = 0.15;

struct Coverage {
  std::size_t input_points = 0;
  std::size_t input_covered = 0;
  std::size_t output_points = 0;
  std::size_t output_on_input = 0;
  std::size_t output_in_gaps = 0;  // output points not surrounded within kGapReach h (measured by the caller)
  // An input point left uncovered, furthest from the output relative to its
  // local spacing (to point at the largest hole); meaningful when some are.
  std::array<double, 3> worst_uncovered{};

  double input_fraction() const;   // 1 for an empty input
  double output_fraction() const;  // 1 for an empty output
  double gap_fraction() const;     // of the output points in gaps; 0 for an empty output
  // Whether the output is short of kLeastInputCovered or kLeastOutputOnInput,
  // or has more than kMostOutputInGaps of its points in gaps.
  bool clear_loss() const;
  // "99.87 % of the 5210 input points covered, 99.95 % of the 9872 output
  // points on the input, 0.00 % in gaps".
  std::string summary() const;
  // Why clear_loss() holds, naming the largest hole; empty when it does not.
  std::string loss_message() const;
};

// Throws std::invalid_argument if h is not positive, the input has at most
// kSpacingNeighbours points or a coordinate is not finite.
template <int D>
Coverage measure_coverage(const std::vector<Vec<D>>& input, const std::vector<Vec<D>>& output, double h);

extern template Coverage measure_coverage<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double);
extern template Coverage measure_coverage<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double);

}  // namespace amls
