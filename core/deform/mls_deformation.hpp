#pragma once
// Moving-least-squares deformation driven by handles: Schaefer, McPhail & Warren,
// "Image deformation using moving least squares" (SIGGRAPH 2006), section 2, and
// its 3D form by Zhu & Gortler, "3D deformation using moving least squares"
// (2007). Each point v gets the affine, similarity or rigid map l_v that best
// takes the handles' start positions p_i to their targets q_i under the weights
// w_i(v) = 1 / |p_i - v|^(2 alpha), and moves to f(v) = l_v(v).
#include <atomic>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "core/deform/deformation.hpp"

namespace amls {

enum class MlsKind { affine, similarity, rigid };

// "affine", "similarity", "rigid".
const char* to_string(MlsKind kind);
// Throws std::invalid_argument naming the accepted values.
MlsKind parse_mls_kind(const std::string& name);

// The best map l_v at one point v.
template <int D>
struct MlsLocalMap {
  Vec<D> position;  // f(v)
  // L in l_v(x) = L (x - p*) + q*. It is the derivative of f at v with the
  // weights frozen (the terms from dw_i/dv are left out, as is standard): carried
  // normals follow L^{-T}. For the rigid kind L is a rotation, for similarity a
  // rotation times a scale.
  Mat<D> linear;
  // Affine only: the weighted moment matrix sum w_i p^_i p^_i^T was singular or
  // ill-conditioned at v (coplanar handles in 3D, collinear in 2D, one handle),
  // so l_v is the similarity map instead.
  bool affine_fell_back = false;
};

// The matrix that carries normals as L^{-T} does, up to their length:
// sign(det L) cof(L) = |det L| L^{-T}. It exists even where L is singular.
template <int D>
Mat<D> normal_transform(const Mat<D>& linear);

// M n renormalised; where that degenerates, n itself.
template <int D>
Vec<D> transform_normal(const Mat<D>& transform, const Vec<D>& normal) {
  const Vec<D> carried = transform * normal;
  const double length = carried.norm();
  return length > 0.0 && std::isfinite(length) ? Vec<D>(carried / length) : normal;
}

// The unit normal n carried by a local map's linear part L: L^{-T} n,
// renormalised; where that degenerates, n itself.
template <int D>
Vec<D> carry_normal(const Mat<D>& linear, const Vec<D>& normal);

// A handle set moving along the straight path from `from` (t = 0) to `to` (t = 1).
// deform(points, t0, t1) maps points by the MLS deformation that takes the
// handles at lerp(t0) to the handles at lerp(t1); map() and apply() are the one
// deformation from `from` to `to`.
template <int D>
class MlsDeformation final : public Deformation<D> {
 public:
  // Throws std::invalid_argument if the handle counts differ, a handle has a
  // non-finite coordinate (the message names its index), or alpha is not > 0.
  MlsDeformation(std::vector<Vec<D>> from, std::vector<Vec<D>> to, MlsKind kind = MlsKind::rigid, double alpha = 1.0);

  // f(v) of the deformation from `from` to `to`. Handles interpolate: f(p_i) = q_i.
  // With no handles f is the identity.
  Vec<D> map(const Vec<D>& v) const { return local_map(v).position; }
  MlsLocalMap<D> local_map(const Vec<D>& v) const;

  // Moves every point by f and carries its normal by L^{-T}, renormalised.
  // Points are independent, so the result does not depend on the thread count.
  void apply(PointSet<D>& points, ThreadPool& pool) const;

  // Maps points from the handles at lerp(t0) to the handles at lerp(t1);
  // t0 and t1 must lie in [0, 1]. deform(points, 0, 1, pool) is apply(points, pool).
  void deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const override;

  // The handles at time t of the path: (1 - t) from + t to.
  std::vector<Vec<D>> handles_at(double t) const;

  const std::vector<Vec<D>>& from() const { return direct_.p; }
  const std::vector<Vec<D>>& to() const { return direct_.q; }
  MlsKind kind() const { return kind_; }

  // 3D rigid and similarity: find the rotation by Newton's polar iteration
  // rather than an SVD where the fit is well conditioned (several times
  // faster). The map is the same to rounding, not bit for bit, so the paper's
  // runs keep it off (the default).
  void use_polar_iteration(bool on) { polar_ = on; }
  double alpha() const { return alpha_; }

  // How many points mapped so far (by map, local_map, apply or deform) had the
  // affine fit fall back to similarity. Always 0 for the other kinds.
  std::size_t fallbacks() const { return fallbacks_.count.load(std::memory_order_relaxed); }
  void reset_fallbacks() const { fallbacks_.count.store(0, std::memory_order_relaxed); }

 private:
  // What the fit at any v needs from one handle configuration.
  struct Handles {
    std::vector<Vec<D>> p, q;
    // Points within this squared distance of a handle are on it (see local_map).
    double snap_squared = 0.0;
  };

  // Counts across threads, yet copies by value so that the deformation stays copyable.
  struct FallbackCounter {
    std::atomic<std::size_t> count{0};
    FallbackCounter() = default;
    FallbackCounter(const FallbackCounter& other) : count(other.count.load()) {}
    FallbackCounter& operator=(const FallbackCounter& other) {
      count.store(other.count.load());
      return *this;
    }
  };

  static Handles make_handles(std::vector<Vec<D>> p, std::vector<Vec<D>> q);
  // `weights` is scratch space for one entry per handle.
  MlsLocalMap<D> evaluate(const Handles& handles, const Vec<D>& v, double* weights) const;
  void transform(const Handles& handles, PointSet<D>& points, ThreadPool& pool) const;

  Handles direct_;
  MlsKind kind_;
  double alpha_;
  bool polar_ = false;
  mutable FallbackCounter fallbacks_;
};

extern template Mat<2> normal_transform<2>(const Mat<2>&);
extern template Mat<3> normal_transform<3>(const Mat<3>&);
extern template Vec<2> carry_normal<2>(const Mat<2>&, const Vec<2>&);
extern template Vec<3> carry_normal<3>(const Mat<3>&, const Vec<3>&);
extern template class MlsDeformation<2>;
extern template class MlsDeformation<3>;

}  // namespace amls
