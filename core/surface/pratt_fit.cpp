#include "core/surface/pratt_fit.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "core/math/small_cholesky.hpp"

namespace amls {

const char* to_string(FitStatus status) {
  switch (status) {
    case FitStatus::ok: return "ok";
    case FitStatus::too_few_neighbours: return "too few neighbours";
    case FitStatus::degenerate: return "degenerate neighbourhood";
    case FitStatus::no_solution: return "no admissible fit";
  }
  return "unknown";
}

namespace {

// Pratt's constraint |b|^2 - 4 a0 a2 as a quadratic form alpha^T C alpha.
template <int M>
Eigen::Matrix<double, M, 1> apply_constraint(const Eigen::Matrix<double, M, 1>& x) {
  Eigen::Matrix<double, M, 1> y = x;
  y[0] = -2.0 * x[M - 1];
  y[M - 1] = -2.0 * x[0];
  return y;
}

// Relative size below which a direction of the neighbourhood's scatter counts as absent.
constexpr double kFlatness = 1e-12;
// Iterations of the fast path before the dense eigensolver takes over.
constexpr int kMaxInverseIterations = 12;
// The unit iterate has converged when it moves less than this: the normal is
// then accurate to about this much, far below what F's accuracy can notice.
// Compared squared, as the iteration measures its steps.
constexpr double kConverged = 1e-12;
constexpr double kConvergedSquared = kConverged * kConverged;
constexpr double kRegularization = 1e-13;

// Whether points whose second moment about p is `scatter` (symmetric) span a
// line (2D) or a plane (3D): its second-largest eigenvalue is not negligible
// next to the largest. By invariants rather than an eigensolver: in 3D the sum of the
// principal 2 x 2 minors over the squared trace is that ratio within a factor
// of 27, plenty for a threshold that only separates zero from rounding noise.
template <int D>
bool spans_hyperplane(const Mat<D>& scatter) {
  const double trace = scatter.trace();
  if (!(trace > 0.0)) return false;
  if constexpr (D == 2) {
    return true;  // the largest of two eigenvalues is positive
  } else {
    const Mat<D>& s = scatter;
    const double minors = s(0, 0) * s(1, 1) - s(0, 1) * s(1, 0) + s(0, 0) * s(2, 2) - s(0, 2) * s(2, 0) +
                          s(1, 1) * s(2, 2) - s(1, 2) * s(2, 1);
    return minors > kFlatness * trace * trace;
  }
}

// The identity's lower triangle, packed.
template <int M>
constexpr std::array<double, kPackedEntries<M>> packed_identity() {
  std::array<double, kPackedEntries<M>> identity{};
  for (int j = 0; j < M; ++j) identity[packed_index<M>(j, j)] = 1.0;
  return identity;
}

// Factors A in every lane. Points exactly on a sphere or plane make A
// singular (that sphere is its null vector, with lambda = 0): such a lane is
// factored again with a relative diagonal shift of kRegularization, which
// makes A invertible and moves the solution by about as much. The other
// lanes' shift is zero, so their factors come out as before. Returns the
// lanes whose A is positive definite, shifted or not.
template <int M, int Pairs>
LaneMasks<Pairs> factor_regularized(LaneLdlt<M, Pairs>& ldlt, const typename LaneLdlt<M, Pairs>::Packed& lower) {
  const LaneMasks<Pairs> positive = ldlt.factor(lower, {});
  bool retry = false;
  Lanes<Pairs> shift{};
  for (int p = 0; p < Pairs; ++p) {
    LanePair trace{};
    for (int j = 0; j < M; ++j) trace += lower[packed_index<M>(j, j)][p];
    shift[p] = select(positive[p], LanePair{}, kRegularization * trace / M);
    retry = retry || (positive[p][0] & positive[p][1]) == 0;
  }
  return retry ? ldlt.factor(lower, shift) : positive;
}

// Scales every lane of x to unit length; returns the squared lengths it had.
// Inlined: a call would spill every live register of the iteration (none is
// callee-saved).
template <int M, int Pairs>
[[gnu::always_inline]] inline Lanes<Pairs> normalize(LaneVector<M, Pairs>& x) {
  Lanes<Pairs> n2{};
  for (int i = 0; i < M; ++i)
    for (int p = 0; p < Pairs; ++p) n2[p] += x[i][p] * x[i][p];
  for (int p = 0; p < Pairs; ++p) {
    // Square roots one lane at a time: the vector extension has none.
    const LanePair inverse_length = 1.0 / LanePair{std::sqrt(n2[p][0]), std::sqrt(n2[p][1])};
    for (int i = 0; i < M; ++i) x[i][p] *= inverse_length;
  }
  return n2;
}

// y = C x in every lane, C as in apply_constraint().
template <int M, int Pairs>
LaneVector<M, Pairs> apply_constraint(const LaneVector<M, Pairs>& x) {
  LaneVector<M, Pairs> y = x;
  for (int p = 0; p < Pairs; ++p) {
    y[0][p] = -2.0 * x[M - 1][p];
    y[M - 1][p] = -2.0 * x[0][p];
  }
  return y;
}

// x^T C x in every lane: Pratt's |b|^2 - 4 a0 a2.
template <int M, int Pairs>
Lanes<Pairs> constraint_form(const LaneVector<M, Pairs>& x) {
  Lanes<Pairs> xcx;
  for (int p = 0; p < Pairs; ++p) {
    xcx[p] = -4.0 * x[0][p] * x[M - 1][p];
    for (int i = 1; i < M - 1; ++i) xcx[p] += x[i][p] * x[i][p];
  }
  return xcx;
}

// For a well-sampled surface the wanted lambda is tiny and the others are
// O(sum of weights), so inverse iteration alpha <- A^-1 C alpha from the plane of
// the carried normal converges in a few steps. It finds the lambda of smallest
// magnitude, which is the wanted one when it is positive: alpha^T C alpha > 0.
// Iterates the `active` lanes of x, each until it converges, where it stays
// (the other lanes' numbers are unspecified). Returns the lanes that
// converged; the others met a zero or overflowing iterate or ran out of iterations.
template <int M, int Pairs>
LaneMasks<Pairs> inverse_iteration(const LaneLdlt<M, Pairs>& ldlt, LaneVector<M, Pairs>& x, LaneMasks<Pairs> active) {
  normalize<M, Pairs>(x);
  LaneMasks<Pairs> converged{};
  // With no previous step the test below reduces to step <= kConverged.
  Lanes<Pairs> previous{};
  for (int it = 0; it < kMaxInverseIterations && any_lane(active); ++it) {
    LaneVector<M, Pairs> next = apply_constraint<M, Pairs>(x);
    ldlt.solve(next);
    const Lanes<Pairs> n2 = normalize<M, Pairs>(next);
    for (int p = 0; p < Pairs; ++p) {
      LanePair step{};
      for (int i = 0; i < M; ++i) step += (next[i][p] - x[i][p]) * (next[i][p] - x[i][p]);
      // The iterates keep their sign once the direction has settled (the
      // eigenvalue is positive), so a vanishing step means convergence. The
      // convergence is linear, so the error left is about step^2 / previous step:
      // stopping on that saves the last iteration. Steps are compared squared.
      const LaneMask done = (step <= kConvergedSquared) | (step * step <= kConvergedSquared * previous[p]);
      // Neither zero nor overflowed (nor NaN): the direction is meaningful.
      const LaneMask usable = (n2[p] > 0.0) & (n2[p] <= std::numeric_limits<double>::max());
      for (int i = 0; i < M; ++i) x[i][p] = select(active[p], next[i][p], x[i][p]);
      converged[p] |= active[p] & usable & done;
      active[p] &= usable & ~done;
      previous[p] = step;
    }
  }
  return converged;
}

}  // namespace

template <int D>
typename PrattFit<D>::Matrix PrattFit<D>::a() const {
  Matrix a;
  int k = 0;
  for (int j = 0; j < kBasis; ++j)
    for (int i = j; i < kBasis; ++i) a(i, j) = a(j, i) = lower_[k++];
  return a;
}

template <int D>
typename PrattFit<D>::Coeffs PrattFit<D>::coefficients() const {
  return alpha_ / std::sqrt(alpha_.dot(apply_constraint<kBasis>(alpha_)));
}

template <int D>
FitStatus PrattFit<D>::check() const {
  if (count_ < D + 1) return FitStatus::too_few_neighbours;
  // The neighbourhood must span a line (2D) or a plane (3D); otherwise the fit's
  // normal is not determined by the data.
  Mat<D> scatter;
  for (int j = 0; j < D; ++j)
    for (int i = j; i < D; ++i) scatter(i, j) = scatter(j, i) = lower_[packed_index<kBasis>(i + 1, j + 1)];
  return spans_hyperplane<D>(scatter) ? FitStatus::ok : FitStatus::degenerate;
}

template <int D>
FitStatus PrattFit<D>::solve(const Vec<D>& carried, Vec<D>& normal) {
  FitStatus status;
  solve_lanes<1>(std::span(this, 1), std::span(&carried, 1), std::span(&normal, 1), std::span(&status, 1));
  return status;
}

template <int D>
template <int Pairs>
void PrattFit<D>::solve_lanes(std::span<PrattFit> fits, std::span<const Vec<D>> carried, std::span<Vec<D>> normals,
                              std::span<FitStatus> status) {
  constexpr int M = kBasis;
  constexpr int kLaneCount = Pairs * kLanesPerPair;
  const int n = static_cast<int>(fits.size());
  // pending: the lanes whose fit wants a solution. Each starts from the plane
  // of its carried normal; the other lanes solve the identity from e_1,
  // harmless numbers that cannot fail.
  std::array<bool, kLaneCount> pending;
  static constexpr std::array<double, kPackedEntries<M>> identity = packed_identity<M>();
  std::array<const double*, kLaneCount> entries;
  std::array<const double*, kLaneCount> start;
  static constexpr std::array<double, D> e0{1.0};
  for (int l = 0; l < kLaneCount; ++l) {
    const std::size_t k = static_cast<std::size_t>(l);
    pending[k] = l < n && (status[k] = fits[k].check()) == FitStatus::ok;
    entries[k] = pending[k] ? fits[k].lower_.data() : identity.data();
    start[k] = pending[k] ? carried[k].data() : e0.data();
  }
  typename LaneLdlt<M, Pairs>::Packed lower;
  LaneVector<M, Pairs> x{};
  LaneVector<D, Pairs> carried_lanes;
  for (int p = 0; p < Pairs; ++p) {
    const std::size_t k = static_cast<std::size_t>(p * kLanesPerPair);
    for (int e = 0; e < kPackedEntries<M>; ++e) lower[e][p] = LanePair{entries[k][e], entries[k + 1][e]};
    for (int i = 0; i < D; ++i) x[i + 1][p] = carried_lanes[i][p] = LanePair{start[k][i], start[k + 1][i]};
  }
  LaneLdlt<M, Pairs> ldlt;
  LaneMasks<Pairs> active = factor_regularized<M, Pairs>(ldlt, lower);
  for (int l = 0; l < kLaneCount; ++l)
    if (!pending[l]) set_lane(active, l, 0);
  LaneMasks<Pairs> settled = inverse_iteration<M, Pairs>(ldlt, x, active);
  const Lanes<Pairs> xcx = constraint_form<M, Pairs>(x);
  for (int p = 0; p < Pairs; ++p) settled[p] &= xcx[p] > 0.0;
  for (int l = 0; l < n; ++l) {
    const std::size_t k = static_cast<std::size_t>(l);
    if (!pending[k] || in_lane(settled, l)) continue;
    // The fallback's eigenvector takes the lane's place for the rest.
    Coeffs eigenvector;
    pending[k] = fits[k].solve_by_eigen_decomposition(eigenvector);
    if (!pending[k]) status[k] = FitStatus::no_solution;
    for (int i = 0; i < M; ++i) set_lane(x[i], l, eigenvector[i]);
  }
  finish_lanes<Pairs>(x, carried_lanes, fits, pending, normals, status);
}

template <int D>
template <int Pairs>
void PrattFit<D>::finish_lanes(const LaneVector<kBasis, Pairs>& x, const LaneVector<D, Pairs>& carried,
                               std::span<PrattFit> fits, const std::array<bool, Pairs * kLanesPerPair>& pending,
                               std::span<Vec<D>> normals, std::span<FitStatus> status) {
  const Lanes<Pairs> xcx = constraint_form<kBasis, Pairs>(x);
  LaneVector<D, Pairs> normal;
  LaneMasks<Pairs> flat;
  for (int p = 0; p < Pairs; ++p) {
    LanePair b2{}, agreement{};
    for (int i = 0; i < D; ++i) {
      b2 += x[i + 1][p] * x[i + 1][p];
      agreement += x[i + 1][p] * carried[i][p];
    }
    // The b of alpha = x / sqrt(xcx) must not vanish.
    flat[p] = ~(b2 > kFlatness * kFlatness * xcx[p]);
    const LanePair length{std::sqrt(b2[0]), std::sqrt(b2[1])};
    const LanePair scale = select(agreement < 0.0, LanePair{-1.0, -1.0}, LanePair{1.0, 1.0}) / length;
    for (int i = 0; i < D; ++i) normal[i][p] = x[i + 1][p] * scale;
  }
  for (int l = 0; l < static_cast<int>(fits.size()); ++l) {
    const std::size_t k = static_cast<std::size_t>(l);
    if (!pending[k]) continue;
    fits[k].alpha_ = lane_vector<kBasis, Pairs>(x, l);
    status[k] = in_lane(flat, l) ? FitStatus::degenerate : FitStatus::ok;
    if (status[k] == FitStatus::ok) normals[k] = lane_vector<D, Pairs>(normal, l);
  }
}

// The general case: eigenpairs of C^-1 A (real for this pencil), keeping the
// smallest non-negative lambda whose eigenvector satisfies alpha^T C alpha > 0.
template <int D>
bool PrattFit<D>::solve_by_eigen_decomposition(Coeffs& eigenvector) const {
  const Matrix a = this->a();
  Matrix c_inverse_a = a;
  c_inverse_a.row(0) = -0.5 * a.row(kBasis - 1);
  c_inverse_a.row(kBasis - 1) = -0.5 * a.row(0);
  const Eigen::EigenSolver<Matrix> solver(c_inverse_a);
  if (solver.info() != Eigen::Success) return false;

  const double tolerance = 1e-12 * a.norm();
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kBasis; ++k) {
    const auto value = solver.eigenvalues()[k];
    if (std::abs(value.imag()) > tolerance || value.real() < -tolerance) continue;
    const Coeffs x = solver.eigenvectors().col(k).real();
    if (!(x.dot(apply_constraint<kBasis>(x)) > 0.0) || value.real() >= best) continue;
    best = value.real();
    eigenvector = x;
  }
  return std::isfinite(best);
}

template class PrattFit<2>;
template class PrattFit<3>;
template void PrattFit<2>::solve_lanes<1>(std::span<PrattFit<2>>, std::span<const Vec<2>>, std::span<Vec<2>>,
                                          std::span<FitStatus>);
template void PrattFit<2>::solve_lanes<PrattFit<2>::kPairs>(std::span<PrattFit<2>>, std::span<const Vec<2>>,
                                                            std::span<Vec<2>>, std::span<FitStatus>);
template void PrattFit<3>::solve_lanes<1>(std::span<PrattFit<3>>, std::span<const Vec<3>>, std::span<Vec<3>>,
                                          std::span<FitStatus>);
template void PrattFit<3>::solve_lanes<PrattFit<3>::kPairs>(std::span<PrattFit<3>>, std::span<const Vec<3>>,
                                                            std::span<Vec<3>>, std::span<FitStatus>);

}  // namespace amls
