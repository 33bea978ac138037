#include "core/pratt_fit.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "core/small_cholesky.hpp"

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
constexpr double kConverged = 1e-12;
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
FitStatus PrattFit<D>::solve(const Vec<D>& carried, Vec<D>& normal) {
  if (count_ < D + 1) return FitStatus::too_few_neighbours;

  // The neighbourhood must span a line (2D) or a plane (3D); otherwise the fit's
  // normal is not determined by the data.
  const Matrix a = this->a();
  if (!spans_hyperplane<D>(a.template block<D, D>(1, 1))) return FitStatus::degenerate;

  Coeffs start = Coeffs::Zero();
  start.template segment<D>(1) = carried;
  if (!solve_by_inverse_iteration(a, start) && !solve_by_eigen_decomposition(a)) return FitStatus::no_solution;

  Vec<D> b = alpha_.template segment<D>(1);
  const double length = b.norm();
  if (!(length > kFlatness)) return FitStatus::degenerate;
  b /= length;
  normal = b.dot(carried) < 0.0 ? Vec<D>(-b) : b;
  return FitStatus::ok;
}

// For a well-sampled surface the wanted lambda is tiny and the others are
// O(sum of weights), so inverse iteration alpha <- A^-1 C alpha from the plane of
// the carried normal converges in a few steps. It finds the lambda of smallest
// magnitude; the caller falls back when that one is not admissible (negative,
// i.e. alpha^T C alpha <= 0) or when A is not positive definite.
template <int D>
bool PrattFit<D>::solve_by_inverse_iteration(const Matrix& a, const Coeffs& start) {
  // Points exactly on a sphere or plane make A singular (that sphere is its
  // null vector, with lambda = 0). A relative diagonal shift of kRegularization
  // makes it invertible and moves the solution by about as much.
  Matrix a_inverse;
  if (!invert_positive_definite<kBasis>(a, a_inverse) &&
      !invert_positive_definite<kBasis>(a + Matrix::Identity() * (kRegularization * a.trace() / kBasis), a_inverse))
    return false;
  // A^-1 C once, so that each iteration is a small matrix-vector product. C
  // maps e_0 to -2 e_last, e_last to -2 e_0 and keeps the others (see
  // apply_constraint()), so A^-1 C is A^-1 with its outer columns swapped and scaled.
  Matrix step_matrix = a_inverse;
  step_matrix.col(0) = -2.0 * a_inverse.col(kBasis - 1);
  step_matrix.col(kBasis - 1) = -2.0 * a_inverse.col(0);
  Coeffs x = start.normalized();
  double previous_step = 0.0;
  for (int it = 0; it < kMaxInverseIterations; ++it) {
    const Coeffs y = step_matrix * x;
    const double n = y.norm();
    if (!std::isfinite(n) || n == 0.0) return false;
    // The iterates keep their sign once the direction has settled (the
    // eigenvalue is positive), so a vanishing step means convergence. The
    // convergence is linear, so the error left is about step^2 / previous step:
    // stopping on that saves the last iteration.
    const Coeffs next = y / n;
    const double step = (next - x).norm();
    x = next;
    const bool converged = step <= kConverged || (it > 0 && step * step <= kConverged * previous_step);
    previous_step = step;
    if (!converged) continue;
    const double xcx = x.dot(apply_constraint<kBasis>(x));
    if (!(xcx > 0.0)) return false;
    alpha_ = x / std::sqrt(xcx);
    return true;
  }
  return false;
}

// The general case: eigenpairs of C^-1 A (real for this pencil), keeping the
// smallest non-negative lambda whose eigenvector satisfies alpha^T C alpha > 0.
template <int D>
bool PrattFit<D>::solve_by_eigen_decomposition(const Matrix& a) {
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
    const double xcx = x.dot(apply_constraint<kBasis>(x));
    if (!(xcx > 0.0) || value.real() >= best) continue;
    best = value.real();
    alpha_ = x / std::sqrt(xcx);
  }
  return std::isfinite(best);
}

template class PrattFit<2>;
template class PrattFit<3>;

}  // namespace amls
