#pragma once
// Moving-least-squares deformation driven by handles: Schaefer, McPhail & Warren,
// "Image deformation using moving least squares" (SIGGRAPH 2006), section 2, and
// its 3D form by Zhu & Gortler, "3D deformation using moving least squares"
// (2007). Each point v gets the affine, similarity or rigid map l_v that best
// takes the handles' start positions p_i to their targets q_i under the weights
// w_i(v) = 1 / |p_i - v|^(2 alpha), and moves to f(v) = l_v(v).
//
// Region handles (region_handle.hpp) join the fit as handles of their own: a
// region moving by M from one place to another adds D + 1 pairs (p, M p) -
// its centre and a point at its extent along each axis, so that together they
// fix M whatever the kind - all weighted by 1 / g^(2 alpha), where g is the
// distance from v to the region's members less its reach. A point within
// reach (g <= 0) is on the region, as a point on a point handle is on it: it
// moves by M exactly, so inside a region the surface is the region moved
// rigidly, and outside the weight grows without bound towards the region's
// edge, so that f meets M there continuously. The region's members do not
// enter the fit one by one: a region costs a nearest-member query (a k-d tree)
// and D + 1 handles, close to a point handle's cost however many members it
// has (docs/design.md compares the alternatives as measured).
#include <atomic>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/deform/deformation.hpp"
#include "core/deform/region_handle.hpp"

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
  // With region handles too: `to_regions` holds the same regions as
  // `from_regions`, in the same order, at their new places. Throws
  // std::invalid_argument also for region counts that differ, a region
  // missing or not the same in both, or a non-finite motion.
  MlsDeformation(std::vector<Vec<D>> from, std::vector<Vec<D>> to, std::vector<RegionHandle<D>> from_regions,
                 std::vector<RegionHandle<D>> to_regions, MlsKind kind = MlsKind::rigid, double alpha = 1.0);

  // f(v) of the deformation from `from` to `to`. Handles interpolate: f(p_i) = q_i.
  // With no handles f is the identity.
  Vec<D> map(const Vec<D>& v) const { return local_map(v).position; }
  MlsLocalMap<D> local_map(const Vec<D>& v) const { return local_map(v, {}); }
  // The same, with each region's gap at v given (one per region, as
  // region_gaps() wrote them; empty: searched for): the gaps depend only on
  // the regions' first places, so a caller that maps the same points by many
  // maps from the same first places (a rest lattice's nodes, step after
  // step) searches the regions' members once. The result is local_map(v)'s,
  // bit for bit. Throws std::invalid_argument for another number of gaps.
  MlsLocalMap<D> local_map(const Vec<D>& v, std::span<const double> gaps) const;

  // Moves every point by f and carries its normal by L^{-T}, renormalised.
  // Points are independent, so the result does not depend on the thread count.
  void apply(PointSet<D>& points, ThreadPool& pool) const;

  // Maps points from the handles at lerp(t0) to the handles at lerp(t1);
  // t0 and t1 must lie in [0, 1]. deform(points, 0, 1, pool) is apply(points, pool).
  void deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const override;

  // The handles at time t of the path: (1 - t) from + t to.
  std::vector<Vec<D>> handles_at(double t) const;
  // The regions at time t: their motions' parameters interpolated (RegionMotion::lerp).
  std::vector<RegionHandle<D>> regions_at(double t) const;

  // The point handles.
  const std::vector<Vec<D>>& from() const { return from_; }
  const std::vector<Vec<D>>& to() const { return to_; }
  const std::vector<RegionHandle<D>>& from_regions() const { return from_regions_; }
  const std::vector<RegionHandle<D>>& to_regions() const { return to_regions_; }
  // No handle of either kind: the identity.
  bool empty() const { return from_.empty() && from_regions_.empty(); }
  // The least distance from v to a region's members less its reach, where
  // the regions are before the map (<= 0 within one; infinite without
  // regions): the map is rigid within reach and changes fast just outside.
  double region_gap(const Vec<D>& v) const;
  // Each region's gap at v, in order (`gaps` holds one per region): their least is region_gap(v).
  void region_gaps(const Vec<D>& v, std::span<double> gaps) const;
  // The first region (in order) whose reach holds v, if any, asked of each
  // region's cells about v rather than of its tree; and the map there, the
  // region's motion: what local_map gives within reach, with no fit.
  std::optional<std::size_t> region_holding(const Vec<D>& v) const;
  MlsLocalMap<D> region_map(std::size_t region, const Vec<D>& v) const;
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
  // A region handle as the fit sees it: where v lies on the region at rest,
  // and the region's map x -> linear x + offset from its first place to its second.
  struct Region {
    const PointRegion<D>* region;
    Mat<D> to_rest;  // rest = to_rest x + rest_offset, the inverse of the first place
    Vec<D> rest_offset;
    double scale;  // of the first place: distances at rest times this are distances at v
    Mat<D> linear;
    Vec<D> offset;
  };

  // What the fit at any v needs from one handle configuration.
  struct Handles {
    // The point handles, then D + 1 pairs for each region (see the header).
    std::vector<Vec<D>> p, q;
    std::size_t points = 0;
    std::vector<Region> regions;
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

  static Handles make_handles(std::vector<Vec<D>> p, std::vector<Vec<D>> q, const std::vector<RegionHandle<D>>& from,
                              const std::vector<RegionHandle<D>>& to);
  // The distance from v to the region's members less its reach, at v's scale.
  static double gap_to(const Region& region, const Vec<D>& v);
  // `weights` is scratch space for one entry per handle; `gaps`, the regions'
  // gaps at v if known (gap_to's), else empty.
  MlsLocalMap<D> evaluate(const Handles& handles, const Vec<D>& v, double* weights, std::span<const double> gaps) const;
  void transform(const Handles& handles, PointSet<D>& points, ThreadPool& pool) const;

  std::vector<Vec<D>> from_, to_;
  std::vector<RegionHandle<D>> from_regions_, to_regions_;
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
