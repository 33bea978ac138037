#pragma once
// Numbers for several independent problems ("lanes") side by side, two to an
// SSE2 register, so that one instruction does the same step for two of them.
// GCC's and Clang's vector extension, written out because GCC does not pair
// up the same loops over plain arrays of lanes reliably.
#include <Eigen/Core>
#include <array>
#include <bit>
#include <cstddef>

namespace amls {

using LanePair = double __attribute__((vector_size(16)));
// What comparing two LanePairs gives: all ones in a lane where it holds, zero elsewhere.
using LaneMask = decltype(LanePair{} < LanePair{});
constexpr int kLanesPerPair = 2;

// One number (or mask) for each of Pairs * 2 lanes; lane l is [l / 2][l % 2].
template <int Pairs>
using Lanes = std::array<LanePair, Pairs>;
template <int Pairs>
using LaneMasks = std::array<LaneMask, Pairs>;

// M numbers for each lane: row i of lane l is lane l of x[i].
template <int M, int Pairs>
using LaneVector = std::array<Lanes<Pairs>, M>;

template <class Pair, std::size_t Pairs>
auto lane_of(const std::array<Pair, Pairs>& v, int l) {
  return v[static_cast<std::size_t>(l / kLanesPerPair)][l % kLanesPerPair];
}

template <class Pair, std::size_t Pairs, class Value>
void set_lane(std::array<Pair, Pairs>& v, int l, Value value) {
  v[static_cast<std::size_t>(l / kLanesPerPair)][l % kLanesPerPair] = value;
}

// Lane l of x, as a vector.
template <int M, int Pairs>
Eigen::Matrix<double, M, 1> lane_vector(const LaneVector<M, Pairs>& x, int l) {
  Eigen::Matrix<double, M, 1> v;
  for (int i = 0; i < M; ++i) v[i] = lane_of(x[static_cast<std::size_t>(i)], l);
  return v;
}

template <std::size_t Pairs>
bool in_lane(const std::array<LaneMask, Pairs>& masks, int l) {
  return lane_of(masks, l) != 0;
}

template <std::size_t Pairs>
bool any_lane(const std::array<LaneMask, Pairs>& masks) {
  LaneMask any{};
  for (const LaneMask& m : masks) any |= m;
  return (any[0] | any[1]) != 0;
}

// a in the lanes of `mask`, b in the others. On the bits: a mask used as a
// condition (mask ? a : b) is first compared with zero, which SSE2 cannot do
// for 64-bit lanes in one instruction.
inline LanePair select(LaneMask mask, LanePair a, LanePair b) {
  return std::bit_cast<LanePair>((mask & std::bit_cast<LaneMask>(a)) | (~mask & std::bit_cast<LaneMask>(b)));
}

}  // namespace amls
