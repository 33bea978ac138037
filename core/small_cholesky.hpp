#pragma once
// The inverse of a small symmetric positive definite matrix by Cholesky
// factorization, in plain loops over compile-time bounds. Eigen's
// LLT::solve(matrix) takes its blocked level-3 path even for a 4 x 4 matrix,
// which cost the Pratt fit about ten times the arithmetic it needs.
#include <Eigen/Core>
#include <cmath>

namespace amls {

// Writes A^-1 to `inverse` from the lower triangle of A (the upper is not
// read). Returns false, leaving `inverse` unspecified, when a pivot is not
// positive, i.e. A is not (numerically) positive definite.
template <int N>
bool invert_positive_definite(const Eigen::Matrix<double, N, N>& a, Eigen::Matrix<double, N, N>& inverse) {
  // A = L L^T, with the reciprocals of L's diagonal kept for the substitutions.
  // Only the lower triangles of l and m below are written or read: zeroing
  // them cost about a fifth of the whole inversion.
  double l[N][N];
  double inverse_diagonal[N];
  for (int j = 0; j < N; ++j) {
    double pivot = a(j, j);
    for (int k = 0; k < j; ++k) pivot -= l[j][k] * l[j][k];
    if (!(pivot > 0.0)) return false;
    const double diagonal = std::sqrt(pivot);
    l[j][j] = diagonal;
    inverse_diagonal[j] = 1.0 / diagonal;
    for (int i = j + 1; i < N; ++i) {
      double s = a(i, j);
      for (int k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
      l[i][j] = s * inverse_diagonal[j];
    }
  }
  // M = L^-1 (lower triangular), column by column by forward substitution.
  double m[N][N];
  for (int c = 0; c < N; ++c) {
    m[c][c] = inverse_diagonal[c];
    for (int i = c + 1; i < N; ++i) {
      double s = 0.0;
      for (int k = c; k < i; ++k) s -= l[i][k] * m[k][c];
      m[i][c] = s * inverse_diagonal[i];
    }
  }
  // A^-1 = M^T M, symmetric.
  // Unrolling the middle loop lets GCC unroll all three; otherwise it keeps
  // them with their exit tests, a third of the function's instructions.
  for (int i = 0; i < N; ++i)
#pragma GCC unroll 8
    for (int j = 0; j <= i; ++j) {
      double s = 0.0;
      for (int k = i; k < N; ++k) s += m[k][i] * m[k][j];
      inverse(i, j) = inverse(j, i) = s;
    }
  return true;
}

}  // namespace amls
