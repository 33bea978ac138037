#include "core/deform/mls_deformation.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace amls {

namespace {

// A point closer to a handle than this fraction of the handles' extent is
// mapped as if it were on the handle. f is continuous there, so the error is of
// this relative size, and the fit never divides by a vanishing distance.
constexpr double kSnapFraction = 1e-12;
// The affine moment matrix counts as singular when its smallest eigenvalue is
// below this fraction of its largest: the handles are then within ~1e-5 of
// their extent from a plane (3D) or line (2D), and the affine map out of that
// plane would be set by rounding noise.
constexpr double kAffineConditionFloor = 1e-10;
// In 3D the covariance has rank one (collinear handles) when its second
// singular value is below this fraction of the first.
constexpr double kRankOneFloor = 1e-10;
// Below this 1 + cos(angle), two directions count as opposite.
constexpr double kOppositeFloor = 1e-12;
// The polar iteration (polar_rotation) runs where det K exceeds this fraction
// of |K|_F^3 (the largest it can be is 3^{-3/2}, about 0.19), and stops when a
// step changes X by less than this (squared, Frobenius): the iteration
// converges quadratically, so X is then within rounding of orthogonal.
constexpr double kPolarDeterminantFloor = 1e-3;
constexpr double kPolarConverged = 1e-20;
// The scaling is dropped once it is this close to 1: near convergence it only costs.
constexpr double kPolarScalingDone = 1e-2;
constexpr int kPolarMaxSteps = 30;

// cof(L) = det(L) L^{-T}, which exists even where L is singular.
Mat<2> cofactor(const Mat<2>& m) {
  Mat<2> c;
  c << m(1, 1), -m(1, 0), -m(0, 1), m(0, 0);
  return c;
}

Mat<3> cofactor(const Mat<3>& m) {
  Mat<3> c;
  c.row(0) = m.row(1).cross(m.row(2));
  c.row(1) = m.row(2).cross(m.row(0));
  c.row(2) = m.row(0).cross(m.row(1));
  return c;
}

// The proper rotation R that maximises tr(R^T K) = sum w_i q^_i . R p^_i for the
// covariance K = sum w_i q^_i p^_i^T, and that maximum, which gives the
// similarity scale.
template <int D>
struct RotationFit {
  Mat<D> rotation;
  double trace;
};

// Schaefer et al., sections 2.2-2.3: in 2D the rotation is the normalised
// (sum w_i p^_i . q^_i, sum w_i p^_i x q^_i), the direction of their mu_s / mu_r
// closed forms. It is proper by construction, and collinear handles only make K
// rank one, which still fixes it.
RotationFit<2> fit_rotation(const Mat<2>& k) {
  const double a = k(0, 0) + k(1, 1);
  const double b = k(1, 0) - k(0, 1);
  const double r = std::hypot(a, b);
  // K = 0 (one handle, or targets that cancel out): every rotation fits alike; take none.
  if (r == 0.0) return {Mat<2>::Identity(), 0.0};
  Mat<2> rotation;
  rotation << a, -b, b, a;
  return {rotation / r, r};
}

// The rotation by the smallest angle that takes unit a to unit b. With
// collinear handles it is the fit that adds no spin about their line, which
// they do not determine.
Mat<3> minimal_rotation(const Vec<3>& a, const Vec<3>& b) {
  const double c = a.dot(b);
  if (c <= -1.0 + kOppositeFloor) {
    // A half turn about any axis normal to a; cross a with the coordinate axis least aligned with it.
    Eigen::Index closest = 0;
    a.cwiseAbs().minCoeff(&closest);
    const Vec<3> axis = a.cross(Vec<3>::Unit(closest)).normalized();
    return 2.0 * axis * axis.transpose() - Mat<3>::Identity();
  }
  // Rodrigues with sin = |k|, cos = c: I + [k]x + [k]x^2 (1 - c) / |k|^2.
  const Vec<3> k = a.cross(b);
  Mat<3> cross;
  cross << 0.0, -k.z(), k.y(), k.z(), 0.0, -k.x(), -k.y(), k.x(), 0.0;
  return Mat<3>::Identity() + cross + cross * cross / (1.0 + c);
}

// Zhu & Gortler: R = U diag(1, 1, d) V^T for K = U S V^T, d = sign det(U V^T).
// Flipping the singular vector of the smallest singular value is the cheapest
// way to avoid a reflection; it costs nothing when that value is zero
// (coplanar handles), where U's last column is any unit normal and the flip
// only picks the one that makes R proper.
RotationFit<3> fit_rotation(const Mat<3>& k) {
  const Eigen::JacobiSVD<Mat<3>> svd(k, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vec<3>& s = svd.singularValues();
  if (s(0) == 0.0) return {Mat<3>::Identity(), 0.0};
  // Rank one: U and V are free about the first singular pair, so the SVD would pick a spin at random.
  if (s(1) <= kRankOneFloor * s(0)) return {minimal_rotation(svd.matrixV().col(0), svd.matrixU().col(0)), s(0)};
  const double d = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  Mat<3> u = svd.matrixU();
  u.col(2) *= d;
  return {u * svd.matrixV().transpose(), s(0) + s(1) + d * s(2)};
}

// The rotation of fit_rotation() by Newton's iteration for the polar factor,
// X <- (g X + X^{-T} / g) / 2, scaled by g = (|X^{-1}|_F / |X|_F)^{1/2}
// (Higham's Frobenius scaling: square roots only, where the determinant
// scaling takes cube roots) until g is near 1. It converges quadratically
// from K itself: a few dozen flops a step against a Jacobi SVD's hundreds.
// Nothing when K is not well inside the proper, full-rank case (det K <= 0
// or small against |K|^3): the SVD's handling of reflections and rank
// deficiency is needed there.
std::optional<RotationFit<3>> polar_rotation(const Mat<3>& k) {
  const double size = k.norm();
  if (!(size > 0.0) || !(k.determinant() > kPolarDeterminantFloor * size * size * size)) return std::nullopt;
  Mat<3> x = k;
  bool scaled = true;
  for (int step = 0; step < kPolarMaxSteps; ++step) {
    const Mat<3> c = cofactor(x);  // det(X) X^{-T}
    const double det = x.row(0).dot(c.row(0));
    double g = 1.0;
    if (scaled) {
      g = std::sqrt(std::sqrt(c.squaredNorm() / x.squaredNorm()) / std::abs(det));
      scaled = std::abs(g - 1.0) >= kPolarScalingDone;
    }
    const Mat<3> next = 0.5 * (g * x + c / (det * g));
    const double change = (next - x).squaredNorm();
    x = next;
    if (change < kPolarConverged) return RotationFit<3>{x, (x.transpose() * k).trace()};
  }
  return std::nullopt;
}

// Section 2.1: L = (sum w_i q^_i p^_i^T)(sum w_i p^_i p^_i^T)^{-1}. False where
// the moment matrix is too close to singular to invert.
template <int D>
bool fit_affine(const Mat<D>& moments, const Mat<D>& covariance, Mat<D>& linear) {
  const Eigen::SelfAdjointEigenSolver<Mat<D>> eigen(moments);
  const Vec<D>& lambda = eigen.eigenvalues();  // ascending
  if (!(lambda(D - 1) > 0.0) || lambda(0) <= kAffineConditionFloor * lambda(D - 1)) return false;
  const Mat<D>& basis = eigen.eigenvectors();
  linear = covariance * basis * lambda.cwiseInverse().asDiagonal() * basis.transpose();
  return true;
}

std::string describe(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void check_time(double t) {
  if (!(t >= 0.0 && t <= 1.0))
    throw std::invalid_argument("MLS deformation: time " + describe(t) + " is outside [0, 1]");
}

}  // namespace

// L^{-T} n = cof(L) n / det L. The cofactor form needs no inverse, so a
// singular L (handles collapsed onto a plane) still gives a direction, and the
// sign of det L keeps the normal pointing to where the outside went.
template <int D>
Mat<D> normal_transform(const Mat<D>& linear) {
  const Mat<D> c = cofactor(linear);
  return linear.determinant() < 0.0 ? Mat<D>(-c) : c;
}

template <int D>
Vec<D> carry_normal(const Mat<D>& linear, const Vec<D>& normal) {
  return transform_normal<D>(normal_transform<D>(linear), normal);
}

const char* to_string(MlsKind kind) {
  switch (kind) {
    case MlsKind::affine:
      return "affine";
    case MlsKind::similarity:
      return "similarity";
    case MlsKind::rigid:
      return "rigid";
  }
  return "?";
}

MlsKind parse_mls_kind(const std::string& name) {
  for (MlsKind kind : {MlsKind::affine, MlsKind::similarity, MlsKind::rigid})
    if (name == to_string(kind)) return kind;
  throw std::invalid_argument("unknown deformation kind '" + name + "' (expected affine, similarity or rigid)");
}

template <int D>
MlsDeformation<D>::MlsDeformation(std::vector<Vec<D>> from, std::vector<Vec<D>> to, MlsKind kind, double alpha)
    : MlsDeformation(std::move(from), std::move(to), {}, {}, kind, alpha) {}

template <int D>
MlsDeformation<D>::MlsDeformation(std::vector<Vec<D>> from, std::vector<Vec<D>> to,
                                  std::vector<RegionHandle<D>> from_regions, std::vector<RegionHandle<D>> to_regions,
                                  MlsKind kind, double alpha)
    : from_(std::move(from)),
      to_(std::move(to)),
      from_regions_(std::move(from_regions)),
      to_regions_(std::move(to_regions)),
      kind_(kind),
      alpha_(alpha) {
  if (from_.size() != to_.size())
    throw std::invalid_argument("MLS deformation: " + std::to_string(from_.size()) + " handle start positions but " +
                                std::to_string(to_.size()) + " targets");
  for (std::size_t i = 0; i < from_.size(); ++i) {
    if (!from_[i].allFinite())
      throw std::invalid_argument("MLS deformation: handle " + std::to_string(i) + " has a non-finite start position");
    if (!to_[i].allFinite())
      throw std::invalid_argument("MLS deformation: handle " + std::to_string(i) + " has a non-finite target");
  }
  if (from_regions_.size() != to_regions_.size())
    throw std::invalid_argument("MLS deformation: " + std::to_string(from_regions_.size()) + " regions at the start but " +
                                std::to_string(to_regions_.size()) + " at the end");
  for (std::size_t r = 0; r < from_regions_.size(); ++r) {
    const std::string which = "MLS deformation: region " + std::to_string(r);
    if (!from_regions_[r].region || from_regions_[r].region != to_regions_[r].region)
      throw std::invalid_argument(which + " is missing or not the same region at the start and the end");
    if (!from_regions_[r].motion.finite() || !to_regions_[r].motion.finite())
      throw std::invalid_argument(which + " has a non-finite motion");
    if (!(from_regions_[r].motion.scale > 0.0) || !(to_regions_[r].motion.scale > 0.0))
      throw std::invalid_argument(which + " has a scale that is not > 0");
  }
  if (!(alpha > 0.0) || !std::isfinite(alpha))
    throw std::invalid_argument("MLS deformation: alpha must be a finite number > 0, got " + describe(alpha));
  direct_ = make_handles(from_, to_, from_regions_, to_regions_);
}

template <int D>
typename MlsDeformation<D>::Handles MlsDeformation<D>::make_handles(std::vector<Vec<D>> p, std::vector<Vec<D>> q,
                                                                    const std::vector<RegionHandle<D>>& from,
                                                                    const std::vector<RegionHandle<D>>& to) {
  Handles handles{std::move(p), std::move(q), 0, {}, 0.0};
  handles.points = handles.p.size();
  for (std::size_t r = 0; r < from.size(); ++r) {
    const PointRegion<D>& region = *from[r].region;
    const Vec<D>& centre = region.centre();
    const Mat<D> first = from[r].motion.linear(), second = to[r].motion.linear();
    const Vec<D> first_offset = from[r].motion.offset(centre), second_offset = to[r].motion.offset(centre);
    Region fit;
    fit.region = &region;
    fit.scale = from[r].motion.scale;
    // first^{-1} = R^T / s for a rotation R scaled by s.
    fit.to_rest = first.transpose() / (fit.scale * fit.scale);
    fit.rest_offset = -fit.to_rest * first_offset;
    fit.linear = second * fit.to_rest;
    fit.offset = second * fit.rest_offset + second_offset;
    handles.regions.push_back(fit);
    // The centre and one point at the region's extent (at least its reach) along each axis.
    const double arm = std::max(region.extent(), region.reach());
    for (int a = -1; a < D; ++a) {
      const Vec<D> rest = a < 0 ? centre : Vec<D>(centre + arm * Vec<D>::Unit(a));
      handles.p.push_back(first * rest + first_offset);
      handles.q.push_back(second * rest + second_offset);
    }
  }
  if (handles.p.empty()) return handles;
  Vec<D> low = handles.p.front(), high = low;
  for (const Vec<D>& x : handles.p) {
    low = low.cwiseMin(x);
    high = high.cwiseMax(x);
  }
  handles.snap_squared = kSnapFraction * kSnapFraction * (high - low).squaredNorm();
  return handles;
}

template <int D>
double MlsDeformation<D>::gap_to(const Region& region, const Vec<D>& v) {
  const Vec<D> rest = region.to_rest * v + region.rest_offset;
  return region.scale * (std::sqrt(region.region->squared_distance(rest)) - region.region->reach());
}

template <int D>
MlsLocalMap<D> MlsDeformation<D>::evaluate(const Handles& handles, const Vec<D>& v, double* weights,
                                           std::span<const double> gaps) const {
  const std::vector<Vec<D>>& p = handles.p;
  const std::vector<Vec<D>>& q = handles.q;
  const std::size_t n = p.size();
  MlsLocalMap<D> local{v, Mat<D>::Identity(), false};
  if (n == 0) return local;

  // A region's pairs all get its gap g squared: the distance from v to its
  // members less its reach (at v's scale). Within reach v is on the region
  // and moves with it.
  for (std::size_t r = 0; r < handles.regions.size(); ++r) {
    const Region& region = handles.regions[r];
    const double gap = gaps.empty() ? gap_to(region, v) : gaps[r];
    if (gap <= 0.0 || gap * gap <= handles.snap_squared) {
      local.linear = region.linear;
      local.position = region.linear * v + region.offset;
      return local;
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(D + 1); ++k)
      weights[handles.points + r * static_cast<std::size_t>(D + 1) + k] = gap * gap;
  }

  // Squared distances first; the nearest handle decides whether v is on one.
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < handles.points; ++i) weights[i] = (p[i] - v).squaredNorm();
  for (std::size_t i = 0; i < n; ++i)
    if (weights[i] < weights[nearest]) nearest = i;
  // On a handle its weight is infinite and f(v) = q_k. L is then the limit of
  // L(v) as v -> p_k: the fit centred at p_k, q_k with the other handles'
  // weights. Handles that coincide with p_k drop out with it.
  const bool on_handle = weights[nearest] <= handles.snap_squared;
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (on_handle && weights[i] <= handles.snap_squared)
      weights[i] = 0.0;
    else
      closest = std::min(closest, weights[i]);
  }
  if (on_handle && closest == std::numeric_limits<double>::infinity()) {
    local.position = q[nearest];
    return local;
  }

  // Every kind's f depends only on the weights' ratios, so scaling them to
  // (d_min^2 / d_i^2)^alpha <= 1 changes nothing but keeps them from overflowing.
  double total = 0.0;
  Vec<D> p_star = Vec<D>::Zero(), q_star = Vec<D>::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] == 0.0) continue;
    const double ratio = closest / weights[i];
    weights[i] = alpha_ == 1.0 ? ratio : std::pow(ratio, alpha_);
    total += weights[i];
    p_star += weights[i] * p[i];
    q_star += weights[i] * q[i];
  }
  if (on_handle) {
    p_star = p[nearest];
    q_star = q[nearest];
  } else {
    p_star /= total;
    q_star /= total;
  }

  // Centred moments, summed as such rather than as sum w p p^T - W p* p*^T,
  // which would cancel when the handles sit far from the origin.
  Mat<D> moments = Mat<D>::Zero(), covariance = Mat<D>::Zero();
  double spread = 0.0;  // sum w_i |p^_i|^2
  for (std::size_t i = 0; i < n; ++i) {
    if (weights[i] == 0.0) continue;
    const Vec<D> p_hat = p[i] - p_star, q_hat = q[i] - q_star;
    covariance += weights[i] * q_hat * p_hat.transpose();
    if (kind_ == MlsKind::affine) moments += weights[i] * p_hat * p_hat.transpose();
    spread += weights[i] * p_hat.squaredNorm();
  }

  if (kind_ != MlsKind::affine || !fit_affine<D>(moments, covariance, local.linear)) {
    local.affine_fell_back = kind_ == MlsKind::affine;
    RotationFit<D> fit;
    if constexpr (D == 3) {
      const std::optional<RotationFit<3>> polar = polar_ ? polar_rotation(covariance) : std::nullopt;
      fit = polar ? *polar : fit_rotation(covariance);
    } else {
      fit = fit_rotation(covariance);
    }
    local.linear = fit.rotation;
    // With every active p^_i zero there is nothing to scale: keep the rotation (here the identity).
    if (kind_ != MlsKind::rigid && spread > 0.0) local.linear *= fit.trace / spread;
  }
  local.position = on_handle ? q[nearest] : Vec<D>(local.linear * (v - p_star) + q_star);
  return local;
}

template <int D>
MlsLocalMap<D> MlsDeformation<D>::local_map(const Vec<D>& v, std::span<const double> gaps) const {
  if (!gaps.empty() && gaps.size() != direct_.regions.size())
    throw std::invalid_argument("MLS deformation: " + std::to_string(gaps.size()) + " region gaps given for " +
                                std::to_string(direct_.regions.size()) + " regions");
  // A point at a time (the lattice's nodes): no allocation for the usual few handles.
  constexpr std::size_t kFewHandles = 16;
  std::array<double, kFewHandles> few;
  std::vector<double> many(direct_.p.size() > kFewHandles ? direct_.p.size() : 0);
  const MlsLocalMap<D> local = evaluate(direct_, v, many.empty() ? few.data() : many.data(), gaps);
  if (local.affine_fell_back) fallbacks_.count.fetch_add(1, std::memory_order_relaxed);
  return local;
}

template <int D>
void MlsDeformation<D>::transform(const Handles& handles, PointSet<D>& points, ThreadPool& pool) const {
  const bool carry_normals = !points.normals.empty();
  if (carry_normals && points.normals.size() != points.size())
    throw std::invalid_argument("MLS deformation: " + std::to_string(points.size()) + " points but " +
                                std::to_string(points.normals.size()) + " normals");
  // No handles, no deformation: leave even the normals' last bits alone.
  if (handles.p.empty()) return;
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    std::vector<double> weights(handles.p.size());
    std::size_t fell_back = 0;
    for (std::size_t i = begin; i < end; ++i) {
      const MlsLocalMap<D> local = evaluate(handles, points.positions[i], weights.data(), {});
      points.positions[i] = local.position;
      if (carry_normals) points.normals[i] = carry_normal<D>(local.linear, points.normals[i]);
      if (local.affine_fell_back) ++fell_back;
    }
    // One update per block, not per point, so that threads do not contend.
    if (fell_back > 0) fallbacks_.count.fetch_add(fell_back, std::memory_order_relaxed);
  });
}

template <int D>
void MlsDeformation<D>::apply(PointSet<D>& points, ThreadPool& pool) const {
  transform(direct_, points, pool);
}

template <int D>
void MlsDeformation<D>::deform(PointSet<D>& points, double t0, double t1, ThreadPool& pool) const {
  check_time(t0);
  check_time(t1);
  if (t0 == t1) return;
  transform(make_handles(handles_at(t0), handles_at(t1), regions_at(t0), regions_at(t1)), points, pool);
}

template <int D>
std::vector<Vec<D>> MlsDeformation<D>::handles_at(double t) const {
  check_time(t);
  std::vector<Vec<D>> handles(from_.size());
  // (1 - t) p + t q is exact at both ends, so deform(0, 1) is apply().
  for (std::size_t i = 0; i < handles.size(); ++i) handles[i] = (1.0 - t) * from_[i] + t * to_[i];
  return handles;
}

template <int D>
std::vector<RegionHandle<D>> MlsDeformation<D>::regions_at(double t) const {
  check_time(t);
  std::vector<RegionHandle<D>> regions = from_regions_;
  for (std::size_t r = 0; r < regions.size(); ++r)
    regions[r].motion = RegionMotion<D>::lerp(from_regions_[r].motion, to_regions_[r].motion, t);
  return regions;
}

template <int D>
double MlsDeformation<D>::region_gap(const Vec<D>& v) const {
  double least = std::numeric_limits<double>::infinity();
  for (const Region& region : direct_.regions) least = std::min(least, gap_to(region, v));
  return least;
}

template <int D>
void MlsDeformation<D>::region_gaps(const Vec<D>& v, std::span<double> gaps) const {
  if (gaps.size() != direct_.regions.size())
    throw std::invalid_argument("MLS deformation: room for " + std::to_string(gaps.size()) + " region gaps, " +
                                std::to_string(direct_.regions.size()) + " regions");
  for (std::size_t r = 0; r < gaps.size(); ++r) gaps[r] = gap_to(direct_.regions[r], v);
}

template <int D>
std::optional<std::size_t> MlsDeformation<D>::region_holding(const Vec<D>& v) const {
  for (std::size_t r = 0; r < direct_.regions.size(); ++r) {
    const Region& region = direct_.regions[r];
    if (region.region->contains(region.to_rest * v + region.rest_offset)) return r;
  }
  return std::nullopt;
}

template <int D>
MlsLocalMap<D> MlsDeformation<D>::region_map(std::size_t region, const Vec<D>& v) const {
  const Region& r = direct_.regions.at(region);
  return {r.linear * v + r.offset, r.linear, false};
}

template Mat<2> normal_transform<2>(const Mat<2>&);
template Mat<3> normal_transform<3>(const Mat<3>&);
template Vec<2> carry_normal<2>(const Mat<2>&, const Vec<2>&);
template Vec<3> carry_normal<3>(const Mat<3>&, const Vec<3>&);
template class MlsDeformation<2>;
template class MlsDeformation<3>;

}  // namespace amls
