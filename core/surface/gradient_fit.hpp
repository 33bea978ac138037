#pragma once
// Step 2 of the AMLS definition (paper, eq. 7) in the limit K -> infinity.
//
// With d_i = p_i - x and f(d) = c + b.d + a |d|^2, the objective is
//   sum_i w_i f(d_i)^2 + K sum_i w_i |b + 2 a d_i - N_i|^2.
// As K grows, the second term alone fixes (b, a): it is a least-squares problem
// in D + 1 unknowns whose normal equations give, with weighted means
// <.> = sum_i w_i (.) / sum_i w_i,
//   a = (<d.N> - <d>.<N>) / (2 (<|d|^2> - |<d>|^2)),   b = <N> - 2 a <d>.
// The constant c does not appear there, so the first term fixes it:
//   c = -(b.<d> + a <|d|^2>).
// F(x) = f(0) = c, and the fitted sphere's gradient at x is b. (See
// tests/test_gradient_fit.cpp for the check that finite-K solves converge to this.)
// With the bias correction (core/surface/surface_offsets.hpp), the neighbours' offsets
// o_i are averaged with the same weights and F(x) = c - <o>.
#include <cmath>

#include "core/math/vec.hpp"

namespace amls {

template <int D>
struct Evaluation {
  bool defined = false;
  double value = 0.0;              // F(x)
  Vec<D> gradient = Vec<D>::Zero();  // gradient of the fitted sphere at x
  Vec<D> mean_normal = Vec<D>::Zero();  // weighted mean of the neighbours' normals: their orientation
};

template <int D>
class GradientFit {
 public:
  GradientFit() = default;
  // A fit from sums a caller accumulated itself (see add() for their meaning).
  GradientFit(double sum_w, const Vec<D>& sum_d, const Vec<D>& sum_n, double sum_dn, double sum_dd,
              double sum_offset = 0.0)
      : sum_w_(sum_w), sum_d_(sum_d), sum_n_(sum_n), sum_dn_(sum_dn), sum_dd_(sum_dd), sum_offset_(sum_offset) {}

  // d: neighbour position minus x; normal: its pseudo-normal; w: its weight
  // (zero adds nothing, so callers can stay free of branches).
  void add(const Vec<D>& d, const Vec<D>& normal, double w) { add(d, d.squaredNorm(), normal, w); }
  // The same with |d|^2 the caller has already computed.
  void add(const Vec<D>& d, double squared_norm, const Vec<D>& normal, double w) {
    sum_w_ += w;
    sum_d_ += w * d;
    sum_n_ += w * normal;
    sum_dn_ += w * d.dot(normal);
    sum_dd_ += w * squared_norm;
  }
  // The same with the neighbour's offset (the bias correction).
  void add(const Vec<D>& d, double squared_norm, const Vec<D>& normal, double w, double offset) {
    add(d, squared_norm, normal, w);
    sum_offset_ += w * offset;
  }

  double total_weight() const { return sum_w_; }

  // F is undefined where less than `min_weight` reaches x, or where the
  // weighted neighbours all coincide (the variance below is zero).
  // Inlined: AmlsSurface::evaluate_in calls it once per evaluation, and GCC
  // leaves it out of line there otherwise (1.7 % more instructions on the
  // 2D vortex, docs/real-data.md).
  [[gnu::always_inline]] Evaluation<D> solve(double min_weight) const {
    Evaluation<D> e;
    if (!(sum_w_ >= min_weight) || sum_w_ <= 0.0) return e;
    const double inverse_w = 1.0 / sum_w_;
    const Vec<D> mean_d = sum_d_ * inverse_w;
    const Vec<D> mean_n = sum_n_ * inverse_w;
    const double mean_dd = sum_dd_ * inverse_w;
    const double variance = mean_dd - mean_d.squaredNorm();
    if (!(variance > 1e-14 * mean_dd)) return e;
    const double a = 0.5 * (sum_dn_ * inverse_w - mean_d.dot(mean_n)) / variance;
    e.gradient = mean_n - 2.0 * a * mean_d;
    e.mean_normal = mean_n;
    e.value = -(e.gradient.dot(mean_d) + a * mean_dd) - sum_offset_ * inverse_w;
    e.defined = std::isfinite(e.value) && e.gradient.allFinite();
    return e;
  }

 private:
  double sum_w_ = 0.0;
  Vec<D> sum_d_ = Vec<D>::Zero();
  Vec<D> sum_n_ = Vec<D>::Zero();
  double sum_dn_ = 0.0;
  double sum_dd_ = 0.0;
  double sum_offset_ = 0.0;
};

}  // namespace amls
