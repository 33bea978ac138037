#pragma once
// LDL^T factorization and solves of small symmetric positive definite
// matrices, several at a time ("lanes", two to an SSE2 register). Each lane's
// numbers go through exactly the operations they would go through alone, so
// a lane's result does not depend on its neighbours. LDL^T needs no square
// roots, and solving with the factors costs what a product with an explicit
// inverse would, without the work of forming that inverse.
#include "core/math/lane_pair.hpp"

namespace amls {

// Entries of a symmetric M x M matrix's lower triangle, packed column by column.
template <int M>
constexpr int kPackedEntries = M * (M + 1) / 2;

// Where entry (i, j), i >= j, of the lower triangle stands in the packed order.
template <int M>
constexpr int packed_index(int i, int j) {
  return j * M - j * (j - 1) / 2 + (i - j);
}

template <int M, int Pairs>
class LaneLdlt {
 public:
  using Packed = std::array<Lanes<Pairs>, kPackedEntries<M>>;

  // Factors, in lane l, the matrix with lower triangle `lower` plus shift I.
  // Returns the lanes whose pivots were all positive, i.e. whose matrix is
  // (numerically) positive definite; the others have unspecified factors.
  LaneMasks<Pairs> factor(const Packed& lower, const Lanes<Pairs>& shift) {
    // The smallest pivot so far, NaN counted as zero: tracked in the pairs, as
    // a branch per lane would split them.
    Lanes<Pairs> smallest;
    smallest.fill(LanePair{1.0, 1.0});
#pragma GCC unroll 8
    for (int j = 0; j < M; ++j) {
      // t[k] = L(j, k) D(k), shared by the pivot and the column below it.
      LaneVector<M, Pairs> t;
#pragma GCC unroll 8
      for (int k = 0; k < j; ++k)
        for (int p = 0; p < Pairs; ++p) t[k][p] = l_[j][k][p] * pivot_[k][p];
      for (int p = 0; p < Pairs; ++p) {
        LanePair pivot = lower[packed_index<M>(j, j)][p] + shift[p];
#pragma GCC unroll 8
        for (int k = 0; k < j; ++k) pivot -= l_[j][k][p] * t[k][p];
        const LanePair clipped = select(pivot > 0.0, pivot, LanePair{});
        smallest[p] = select(clipped < smallest[p], clipped, smallest[p]);
        pivot_[j][p] = pivot;
        inverse_pivot_[j][p] = 1.0 / pivot;
      }
#pragma GCC unroll 8
      for (int i = j + 1; i < M; ++i)
        for (int p = 0; p < Pairs; ++p) {
          LanePair s = lower[packed_index<M>(i, j)][p];
#pragma GCC unroll 8
          for (int k = 0; k < j; ++k) s -= l_[i][k][p] * t[k][p];
          l_[i][j][p] = s * inverse_pivot_[j][p];
        }
    }
    LaneMasks<Pairs> positive;
    for (int p = 0; p < Pairs; ++p) positive[p] = smallest[p] > 0.0;
    return positive;
  }

  // Overwrites x with (L D L^T)^-1 x, lane by lane.
  void solve(LaneVector<M, Pairs>& x) const {
#pragma GCC unroll 8
    for (int i = 1; i < M; ++i)
#pragma GCC unroll 8
      for (int k = 0; k < i; ++k)
        for (int p = 0; p < Pairs; ++p) x[i][p] -= l_[i][k][p] * x[k][p];
#pragma GCC unroll 8
    for (int i = 0; i < M; ++i)
      for (int p = 0; p < Pairs; ++p) x[i][p] *= inverse_pivot_[i][p];
#pragma GCC unroll 8
    for (int i = M - 2; i >= 0; --i)
#pragma GCC unroll 8
      for (int k = i + 1; k < M; ++k)
        for (int p = 0; p < Pairs; ++p) x[i][p] -= l_[k][i][p] * x[k][p];
  }

 private:
  // Only the strict lower triangle of l_ is written or read.
  Lanes<Pairs> l_[M][M];
  Lanes<Pairs> pivot_[M];
  Lanes<Pairs> inverse_pivot_[M];
};

}  // namespace amls
