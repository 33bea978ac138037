#pragma once
// Step 1 of the AMLS definition (paper, section 2, eqs. 4-6): the pseudo-normal
// at a point is the normal of the algebraic sphere f(u) = a0 + b.u + a2 |u|^2
// that minimises sum_j w_j f(u_j)^2 under Pratt's constraint |b|^2 - 4 a0 a2 = 1.
// With the basis q(u) = (1, u, |u|^2), A = sum_j w_j q(u_j) q(u_j)^T and the
// constraint matrix C, the minimiser is the eigenvector of A alpha = lambda C alpha
// with the smallest non-negative lambda. Coordinates are centred at the point and
// scaled by Delta, so A is well conditioned and the normal is b / |b|.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <span>

#include "core/math/lane_pair.hpp"
#include "core/math/vec.hpp"

namespace amls {

enum class FitStatus {
  ok,
  too_few_neighbours,  // fewer weighted neighbours than the fit has degrees of freedom
  degenerate,          // all neighbours coincide, or (3D) they lie on one line
  no_solution,         // the eigenproblem has no admissible eigenvector
};

const char* to_string(FitStatus status);

template <int D>
class PrattFit {
 public:
  static constexpr int kBasis = D + 2;
  // How many pairs of fits solve_lanes() takes at once, besides one pair.
  static constexpr int kPairs = 2;
  using Coeffs = Eigen::Matrix<double, kBasis, 1>;
  using Matrix = Eigen::Matrix<double, kBasis, kBasis>;

  // u: neighbour position relative to the point, divided by Delta; w: its weight.
  void add(const Vec<D>& u, double w) {
    if (w <= 0.0) return;
    Coeffs q;
    q[0] = 1.0;
    q.template segment<D>(1) = u;
    q[D + 1] = u.squaredNorm();
    // Only the lower triangle, packed column by column: the LDL^T
    // factorization reads no more, and a() unpacks it. Packed, consecutive
    // entries pair up for SSE2 (in 2D the ten are five pairs) and the fit
    // holds no padding for the loop to zero.
    int k = 0;
    for (int j = 0; j < kBasis; ++j) {
      const double wq = w * q[j];
      for (int i = j; i < kBasis; ++i) lower_[k++] += wq * q[i];
    }
    ++count_;
  }

  // Solves the fit; on success writes the unit normal, oriented to agree with
  // `carried`, to `normal`. On failure `normal` is left untouched.
  FitStatus solve(const Vec<D>& carried, Vec<D>& normal);

  // solve() for up to 2 Pairs fits at once: fits[k] with carried[k] writes
  // normals[k] and status[k]. Their inverse iterations run side by side (see
  // LaneLdlt), each fit stopping at its own convergence, so every fit gets
  // exactly what solve() gives it alone.
  template <int Pairs>
  static void solve_lanes(std::span<PrattFit> fits, std::span<const Vec<D>> carried, std::span<Vec<D>> normals,
                          std::span<FitStatus> status);

  // The neighbours' weighted centroid, in the fit's coordinates (relative to
  // the point, in units of its support); zero when no weight was added.
  Vec<D> weighted_centroid() const {
    if (lower_[0] <= 0.0) return Vec<D>::Zero();
    Vec<D> sum;
    for (int a = 0; a < D; ++a) sum[a] = lower_[1 + a];  // column 0 of A below its first entry: sum w u
    return sum / lower_[0];
  }

  // The fitted coefficients (a0, b, a2) of the last solve that found the
  // eigenvector, scaled so that alpha^T C alpha = 1.
  Coeffs coefficients() const;

 private:
  // Whether the neighbourhood can determine a fit at all.
  FitStatus check() const;
  // From each pending lane's eigenvector x (any scale, x^T C x > 0): keeps
  // x in its fit and writes the normal and status.
  template <int Pairs>
  static void finish_lanes(const LaneVector<kBasis, Pairs>& x, const LaneVector<D, Pairs>& carried,
                           std::span<PrattFit> fits, const std::array<bool, Pairs * kLanesPerPair>& pending,
                           std::span<Vec<D>> normals, std::span<FitStatus> status);
  // The dense eigensolver, for the fits inverse iteration does not settle.
  // Writes the admissible eigenvector if there is one.
  bool solve_by_eigen_decomposition(Coeffs& eigenvector) const;

  // A, whole and symmetric.
  Matrix a() const;

  // A's lower triangle, column by column. Its block of rows and columns 1..D
  // is the neighbours' weighted second moment about the point, which the
  // degeneracy test reads.
  std::array<double, kBasis*(kBasis + 1) / 2> lower_{};
  int count_ = 0;
  // The eigenvector of the last solve that found one, unscaled.
  Coeffs alpha_ = Coeffs::Zero();
};

// The fits of consecutive points [begin, end), solved kLanes at a time with
// solve_lanes(): start(i) hands out point i's fit to fill, solving the batch
// before it once that is full, and finish() solves the last. Point i's
// normal goes to normals[i], carried[i] where the fit fails, and its status
// to status[i].
template <int D>
class PrattBatches {
 public:
  static constexpr std::size_t kLanes = 2 * PrattFit<D>::kPairs;

  PrattBatches(std::span<const Vec<D>> carried, std::span<Vec<D>> normals, std::span<FitStatus> status,
               std::size_t begin)
      : carried_(carried), normals_(normals), status_(status), batch_begin_(begin) {}

  PrattFit<D>& start(std::size_t i) {
    if (i - batch_begin_ == kLanes) solve_until(i);
    return fits_[i - batch_begin_] = PrattFit<D>();
  }
  void finish(std::size_t end) { solve_until(end); }

 private:
  void solve_until(std::size_t end) {
    const std::size_t count = end - batch_begin_;
    const std::span<Vec<D>> normals = normals_.subspan(batch_begin_, count);
    const std::span<const Vec<D>> carried = carried_.subspan(batch_begin_, count);
    std::copy(carried.begin(), carried.end(), normals.begin());  // kept where a fit fails
    PrattFit<D>::template solve_lanes<PrattFit<D>::kPairs>(
        std::span(fits_).first(count), carried, normals, status_.subspan(batch_begin_, count));
    batch_begin_ = end;
  }

  std::span<const Vec<D>> carried_;
  std::span<Vec<D>> normals_;
  std::span<FitStatus> status_;
  std::array<PrattFit<D>, kLanes> fits_;
  std::size_t batch_begin_;
};

extern template class PrattFit<2>;
extern template class PrattFit<3>;

}  // namespace amls
