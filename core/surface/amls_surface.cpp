#include "core/surface/amls_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/surface/local_support.hpp"
#include "core/surface/surface_offsets.hpp"
#include "core/math/weight.hpp"
#include "core/util/parameter_ranges.hpp"

namespace amls {

template <int D>
AmlsSurface<D>::AmlsSurface(const Grid<D>& grid, const AmlsParameters& parameters)
    : grid_(grid), parameters_(parameters), radius_(parameters.radius_factor * grid.spacing()) {
  check_range("radius factor", parameters.radius_factor, ranges::kRadiusFactor);
  check_range("minimum weight", parameters.min_weight, ranges::kMinWeight);
}

template <int D>
void AmlsSurface<D>::set_points(PointSet<D> points) {
  if (points.normals.size() != points.positions.size())
    throw std::invalid_argument("point set has " + std::to_string(points.positions.size()) + " positions but " +
                                std::to_string(points.normals.size()) + " normals");
  if (!points.rim.empty() && points.rim.size() != points.positions.size())
    throw std::invalid_argument("point set has " + std::to_string(points.positions.size()) + " positions but " +
                                std::to_string(points.rim.size()) + " rim marks");
  points_ = std::move(points);
  given_radii_.reset();
  rim_ = SurfaceRim<D>();
  hashed_ = ready_ = false;
}

template <int D>
void AmlsSurface<D>::set_points(PointSet<D> points, std::vector<double> support_radii) {
  if (support_radii.size() != points.positions.size())
    throw std::invalid_argument("point set has " + std::to_string(points.positions.size()) + " positions but " +
                                std::to_string(support_radii.size()) + " support radii");
  set_points(std::move(points));
  given_radii_ = std::move(support_radii);
}

template <int D>
void AmlsSurface<D>::hash_points() {
  ThreadPool serial(1);
  hash_points(serial);
}

template <int D>
void AmlsSurface<D>::hash_points(ThreadPool& pool) {
  // Not hashed until the index is whole (the build can throw, or be cancelled).
  hashed_ = ready_ = false;
  rim_ = SurfaceRim<D>();  // its ids are the old order's
  support_radii_.clear();
  inverse_r2_.clear();
  wide_ids_.clear();
  supports_measured_ = false;
  index_.build(points_.positions, grid_.origin(), radius_, pool);
  // Reorder the points by cell, so that a neighbourhood is a few contiguous runs.
  const std::vector<std::uint32_t>& order = index_.order();
  PointSet<D> sorted;
  sorted.positions.resize(order.size());
  sorted.normals.resize(order.size());
  sorted.rim.resize(points_.rim.empty() ? 0 : order.size());
  std::vector<double> radii(given_radii_ ? order.size() : 0);
  pool.parallel_for(order.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      sorted.positions[k] = points_.positions[order[k]];
      sorted.normals[k] = points_.normals[order[k]];
    }
    if (!sorted.rim.empty())
      for (std::size_t k = begin; k < end; ++k) sorted.rim[k] = points_.rim[order[k]];
    if (given_radii_)
      for (std::size_t k = begin; k < end; ++k) radii[k] = (*given_radii_)[order[k]];
  });
  points_ = std::move(sorted);
  if (given_radii_) given_radii_ = std::move(radii);
  index_.renumber_in_cell_order();
  hashed_ = true;
  ready_ = false;
}

template <int D>
void AmlsSurface<D>::widen_supports(ThreadPool& pool) {
  if (given_radii_)
    support_radii_ = std::any_of(given_radii_->begin(), given_radii_->end(), [&](double r) { return r > radius_; })
                         ? *given_radii_
                         : std::vector<double>{};
  else
    support_radii_ = widened_support_radii<D>(points_.positions, radius_, grid_.spacing(), pool);
  supports_measured_ = true;
  if (!widened()) return;
  inverse_r2_.resize(support_radii_.size());
  std::vector<Vec<D>> wide_positions;
  widest_ = radius_;
  for (std::uint32_t k = 0; k < support_radii_.size(); ++k) {
    inverse_r2_[k] = 1.0 / (support_radii_[k] * support_radii_[k]);
    if (support_radii_[k] > radius_) {
      wide_ids_.push_back(k);
      wide_positions.push_back(points_.positions[k]);
      widest_ = std::max(widest_, support_radii_[k]);
    }
  }
  wide_index_.build(wide_positions, grid_.origin(), widest_, pool);
}

// How update_normals() measures neighbour j from point i: its offset in the
// fit's coordinates (scaled by i's support, which keeps A well conditioned
// and does not change the fitted normal) and |p_j - p_i|^2 / Delta_j^2, which
// weighs it. One Delta for all, or each point's own.
template <int D>
struct AmlsSurface<D>::UniformSupport {
  static constexpr bool kWidened = false;
  double inverse_radius;
  double measure(const Vec<D>& offset, std::uint32_t, std::size_t, Vec<D>& u) const {
    u = offset * inverse_radius;
    return u.squaredNorm();
  }
};

template <int D>
struct AmlsSurface<D>::WidenedSupport {
  static constexpr bool kWidened = true;
  const std::vector<double>& radii;
  const std::vector<double>& inverse_r2;
  // Between two points of one support, the uniform measure's very
  // arithmetic: a local resample whose support widens nothing takes the
  // uniform path, and there its fits must be the whole surface's bit for bit.
  double measure(const Vec<D>& offset, std::uint32_t j, std::size_t i, Vec<D>& u) const {
    u = offset * (1.0 / radii[i]);
    return radii[j] == radii[i] ? u.squaredNorm() : offset.squaredNorm() * inverse_r2[j];
  }
};

template <int D>
NormalStats AmlsSurface<D>::update_normals(ThreadPool& pool) {
  if (!hashed_) hash_points(pool);
  // The supports follow the points as hashed, once per hash.
  if ((parameters_.widen_support || given_radii_) && !supports_measured_) widen_supports(pool);
  const std::size_t n = points_.size();
  pseudo_normals_.resize(n);
  std::vector<FitStatus> status(n);
  // The bias correction reads every point's neighbours again: listed by the
  // fits, where they are found anyway.
  const bool list_neighbours = D == 3 && parameters_.bias_correction;
  if (list_neighbours) neighbours_.reset(n, pool.threads());
  if (widened())
    fit_normals(WidenedSupport{support_radii_, inverse_r2_}, status, pool);
  else
    fit_normals(UniformSupport{1.0 / radius_}, status, pool);
  NormalStats stats;
  for (FitStatus s : status) stats.count(s);
  stats.widened = wide_ids_.size();
  find_rim(pool);
  offsets_.clear();
  if constexpr (D == 3) {
    if (list_neighbours)
      offsets_ = surface_offsets<D>(points_.positions, pseudo_normals_, neighbours_,
                                    {radius_, parameters_.min_weight, parameters_.orientation_filter, inverse_r2_},
                                    pool);
  }
  ready_ = true;
  return stats;
}

template <int D>
template <typename Support>
void AmlsSurface<D>::fit_normals(const Support& support, std::vector<FitStatus>& status, ThreadPool& pool) {
  const bool filter = parameters_.orientation_filter;
  const bool list_neighbours = D == 3 && parameters_.bias_correction;
  const bool flag_rims = parameters_.keep_rims;
  rim_candidates_.assign(flag_rims ? points_.size() : 0, 0);
  pool.parallel_for(points_.size(), [&](std::size_t begin, std::size_t end, int block) {
    // Points are in cell order, so consecutive points share their candidate
    // neighbours: every point of the 3^D cells around their cell.
    std::vector<std::uint32_t> candidates;
    IVec<D> candidates_cell = IVec<D>::Zero();
    bool have_candidates = false;
    // Fits are solved a batch at a time, after their sums, side by side in
    // SSE2 lanes (PrattFit::solve_lanes); each point gets what it would get
    // alone. A failed fit leaves the carried normal.
    PrattBatches<D> fits(points_.normals, pseudo_normals_, status, begin);
    for (std::size_t i = begin; i < end; ++i) {
      const Vec<D>& p = points_.positions[i];
      const IVec<D> cell = index_.cell_of(p);
      if (!have_candidates || cell != candidates_cell) {
        have_candidates = true;
        candidates.clear();
        if constexpr (Support::kWidened) {
          // Every point whose support reaches the cell.
          const Vec<D> cell_lo = grid_.origin() + radius_ * cell.template cast<double>();
          const Vec<D> cell_hi = cell_lo.array() + radius_;
          index_.gather(cell_lo, cell_hi, radius_, candidates);
          gather_widened(cell_lo, cell_hi, radius_, candidates);
        } else {
          index_.for_each_in_cells(cell.array() - 1, cell.array() + 1,
                                   [&](std::uint32_t id, const Vec<D>&) { candidates.push_back(id); });
        }
        candidates_cell = cell;
      }
      const Vec<D>& own = points_.normals[i];
      PrattFit<D>& fit = fits.start(i);
      std::vector<std::uint32_t>* listed = list_neighbours ? &neighbours_.start(i, block) : nullptr;
      for (const std::uint32_t id : candidates) {
        Vec<D> u;
        const double s2 = support.measure(points_.positions[id] - p, id, i, u);
        if (s2 > 1.0) continue;
        if (listed) listed->push_back(id);
        if (filter && !agrees(points_.normals[id], own)) continue;
        fit.add(u, weight_of_squared_ratio(s2));
      }
      if (listed) neighbours_.finish(i, block);
      if (flag_rims) {
        const Vec<D> shift = fit.weighted_centroid();
        const Vec<D> tangential = shift - own * shift.dot(own);
        rim_candidates_[i] = tangential.squaredNorm() > kRimCandidateShift * kRimCandidateShift;
      }
    }
    fits.finish(end);
  });
}

template <int D>
void AmlsSurface<D>::find_rim(ThreadPool& pool) {
  rim_ = SurfaceRim<D>();
  std::vector<std::uint32_t> candidates;
  // A point carried as rim is tested whatever its centroid says.
  for (std::uint32_t i = 0; i < rim_candidates_.size(); ++i)
    if (rim_candidates_[i] || points_.on_rim(i)) candidates.push_back(i);
  if (candidates.empty()) return;
  // Each candidate's neighbours within kRimReach supports (or whose own
  // support reaches that far), seen in its tangent plane. Their normals
  // must not face away (within 120 degrees of its own): the other side of a
  // thin sheet is no neighbour, but the other face of a sharp edge is.
  std::vector<std::optional<Vec<D>>> outward(candidates.size());
  pool.parallel_for(candidates.size(), [&](std::size_t begin, std::size_t end, int) {
    std::vector<std::uint32_t> ids;
    std::vector<RimNeighbour<D>> neighbours;
    for (std::size_t c = begin; c < end; ++c) {
      const std::uint32_t i = candidates[c];
      const Vec<D>& p = points_.positions[i];
      const Vec<D>& n = pseudo_normals_[i];
      const double own = support_radius(i);
      ids.clear();
      neighbours.clear();
      index_.gather(p, p, kRimReach * own, ids);
      if (widened()) gather_widened(p, p, kRimReach * own, ids);
      for (const std::uint32_t j : ids) {
        const Vec<D> offset = points_.positions[j] - p;
        const double reach = kRimReach * std::max(own, support_radius(j));
        if (j == i || offset.squaredNorm() > reach * reach || pseudo_normals_[j].dot(n) < kRimFacing) continue;
        neighbours.push_back({offset, 0.5 * kRimBridge * (own + support_radius(j))});
      }
      outward[c] = rim_outward<D>(n, neighbours, points_.on_rim(i));
    }
  });
  typename SurfaceRim<D>::Samples samples;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!outward[c]) continue;
    const std::uint32_t i = candidates[c];
    samples.ids.push_back(i);
    samples.positions.push_back(points_.positions[i]);
    samples.outward.push_back(*outward[c]);
    samples.normals.push_back(pseudo_normals_[i]);
    samples.radii.push_back(support_radius(i));
  }
  rim_ = SurfaceRim<D>(std::move(samples), grid_.origin());
}

template <int D>
void AmlsSurface<D>::require_ready() const {
  if (!ready_) throw std::logic_error("AmlsSurface evaluated before hash_points() and update_normals()");
}

template <int D>
Evaluation<D> AmlsSurface<D>::evaluate(const Vec<D>& x) const {
  // Reused per thread: evaluate() runs on pool threads, and allocating at
  // every call would cost more than the fit.
  thread_local std::vector<std::uint32_t> ids;
  thread_local Neighbourhood<D> neighbourhood;
  ids.clear();
  gather_ids(x, x, radius_, ids);
  select(ids, x, radius_, neighbourhood);
  return evaluate_in(neighbourhood, x);
}

template <int D>
bool AmlsSurface<D>::has_point_within(const Vec<D>& x, double radius) const {
  require_ready();
  bool found = false;
  index_.for_each_within(x, radius, [&](std::uint32_t, const Vec<D>&) { found = true; });
  return found;
}

template <int D>
void AmlsSurface<D>::gather_ids(const Vec<D>& lo, const Vec<D>& hi, double radius,
                                std::vector<std::uint32_t>& out) const {
  require_ready();
  index_.gather(lo, hi, radius, out);
  if (widened()) gather_widened(lo, hi, radius, out);
}

template <int D>
void AmlsSurface<D>::gather_widened(const Vec<D>& lo, const Vec<D>& hi, double radius,
                                    std::vector<std::uint32_t>& out) const {
  thread_local std::vector<std::uint32_t> wide;
  wide.clear();
  const double margin = radius - radius_;
  wide_index_.gather(lo, hi, margin + widest_, wide);
  const double r2 = radius * radius;
  const std::size_t first = out.size();
  for (const std::uint32_t k : wide) {
    const std::uint32_t id = wide_ids_[k];
    const Vec<D>& q = points_.positions[id];
    const double outside2 = (lo - q).cwiseMax(q - hi).cwiseMax(0.0).squaredNorm();
    const double reach = margin + support_radii_[id];
    // Those within `radius` are in `out` already.
    if (outside2 > r2 && outside2 <= reach * reach) out.push_back(id);
  }
  // In the points' order, not the wide index's: its cells are as wide as the
  // widest Delta_i, which differs between a local resample's support and the
  // whole surface, and the order of the sums over neighbours decides F's last
  // bits (inside R a local resample is the whole surface's, bit for bit).
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

template <int D>
void AmlsSurface<D>::select(std::span<const std::uint32_t> ids, const Vec<D>& x, double radius,
                            Neighbourhood<D>& out) const {
  if (widened())
    select_with<true>(ids, x, radius, out);
  else
    select_with<false>(ids, x, radius, out);
}

template <int D>
template <bool kWidened>
void AmlsSurface<D>::select_with(std::span<const std::uint32_t> ids, const Vec<D>& x, double radius,
                                 Neighbourhood<D>& out) const {
  // Sized for every candidate, then cut to those kept: no capacity checks in
  // the loop. Every candidate is written and only those within reach kept: no
  // branch on the distance, which is hard to predict.
  const bool corrected = !offsets_.empty();
  out.positions.resize(ids.size());
  out.normals.resize(ids.size());
  out.offsets.resize(corrected ? ids.size() : 0);
  if constexpr (kWidened)
    out.inverse_r2.resize(ids.size());
  else
    out.inverse_r2.clear();
  const double r2 = radius * radius;
  std::size_t kept = 0;
  for (const std::uint32_t id : ids) {
    const Vec<D>& q = points_.positions[id];
    out.positions[kept] = q;
    out.normals[kept] = pseudo_normals_[id];
    if (corrected) out.offsets[kept] = offsets_[id];
    if constexpr (kWidened) {
      out.inverse_r2[kept] = inverse_r2_[id];
      const double reach = radius - radius_ + support_radii_[id];
      kept += (q - x).squaredNorm() > reach * reach ? 0 : 1;
    } else {
      kept += (q - x).squaredNorm() > r2 ? 0 : 1;
    }
  }
  out.positions.resize(kept);
  out.normals.resize(kept);
  out.offsets.resize(corrected ? kept : 0);
  if constexpr (kWidened) out.inverse_r2.resize(kept);
  Vec<D> sum = Vec<D>::Zero();
  for (const Vec<D>& n : out.normals) sum += n;
  // Every normal within 45 degrees of the sum s: n.s > |s| cos 45 degrees,
  // squared so that no square root holds up the test.
  const double half_sum2 = 0.5 * sum.squaredNorm();
  out.consistent = std::all_of(out.normals.begin(), out.normals.end(), [&](const Vec<D>& n) {
    const double along = n.dot(sum);
    return along > 0.0 && along * along > half_sum2;
  });
}

template <int D>
Evaluation<D> AmlsSurface<D>::evaluate_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& y) const {
  const GradientFit<D> fit =
      neighbourhood.inverse_r2.empty() ? fit_in<false>(neighbourhood, y) : fit_in<true>(neighbourhood, y);
  return fit.solve(parameters_.min_weight);
}

template <int D>
template <bool kWidened>
GradientFit<D> AmlsSurface<D>::fit_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& y) const {
  // (Widened: the support test below bounds the search.)
  const double r2 = kWidened ? std::numeric_limits<double>::infinity() : radius_ * radius_;
  const std::size_t n = neighbourhood.positions.size();
  const bool filter = filters(neighbourhood);
  // The orientation reference: the pseudo-normal of the nearest point whose
  // support reaches y. (Recomputing distances in the second pass is cheaper
  // than storing them.) Tracked by index with selects, not branches: which
  // neighbour is nearer than the ones before it is unpredictable.
  Vec<D> reference = Vec<D>::Zero();
  if (filter) {
    double nearest = r2;
    std::size_t nearest_k = n;
    for (std::size_t k = 0; k < n; ++k) {
      const double d2 = (neighbourhood.positions[k] - y).squaredNorm();
      bool nearer = d2 < nearest;
      if constexpr (kWidened) nearer = nearer & (d2 * neighbourhood.inverse_r2[k] < 1.0);
      nearest = nearer ? d2 : nearest;
      nearest_k = nearer ? k : nearest_k;
    }
    if (nearest_k < n) reference = neighbourhood.normals[nearest_k];
  }
  const double inverse_r2 = 1.0 / r2;
  GradientFit<D> fit;
  // Branch-free: a neighbour beyond its support or filtered out adds with weight 0.
  auto add_all = [&](auto&& add) {
    for (std::size_t k = 0; k < n; ++k) {
      const Vec<D> d = neighbourhood.positions[k] - y;
      const double dd = d.squaredNorm();
      const bool kept = !filter || agrees(neighbourhood.normals[k], reference);
      const double s2 = dd * (kWidened ? neighbourhood.inverse_r2[k] : inverse_r2);
      add(k, d, dd, weight_of_squared_ratio(s2) * static_cast<double>(kept));
    }
  };
  if (neighbourhood.offsets.empty())
    add_all([&](std::size_t k, const Vec<D>& d, double dd, double w) { fit.add(d, dd, neighbourhood.normals[k], w); });
  else
    add_all([&](std::size_t k, const Vec<D>& d, double dd, double w) {
      fit.add(d, dd, neighbourhood.normals[k], w, neighbourhood.offsets[k]);
    });
  return fit;
}

template <int D>
void AmlsSurface<D>::evaluate_cube(const Neighbourhood<D>& neighbourhood,
                                   const std::array<Vec<D>, kCubeCorners>& corners,
                                   std::array<Evaluation<D>, kCubeCorners>& out) const {
  if (filters(neighbourhood)) {
    // Each corner has its own orientation reference: one at a time.
    for (int v = 0; v < kCubeCorners; ++v) out[v] = evaluate_in(neighbourhood, corners[v]);
  } else if (!neighbourhood.inverse_r2.empty()) {
    if (neighbourhood.offsets.empty())
      evaluate_cube_with<false, true>(neighbourhood, corners, out);
    else
      evaluate_cube_with<true, true>(neighbourhood, corners, out);
  } else if (neighbourhood.offsets.empty()) {
    evaluate_cube_with<false, false>(neighbourhood, corners, out);
  } else {
    evaluate_cube_with<true, false>(neighbourhood, corners, out);
  }
}

template <int D>
template <bool kCorrected, bool kWidened>
void AmlsSurface<D>::evaluate_cube_with(const Neighbourhood<D>& neighbourhood,
                                        const std::array<Vec<D>, kCubeCorners>& corners,
                                        std::array<Evaluation<D>, kCubeCorners>& out) const {
  constexpr int V = kCubeCorners;
  // Structure of arrays over the corners, so that each line below is one
  // vector operation across them. Coordinates are taken from the cube's
  // centre c, with q = p - c for a neighbour p and y the corner: then
  // d = q - y, |d|^2 = |q|^2 - 2 q.y + |y|^2, sum w d = sum w q - y sum w and
  // sum w d.n = sum w q.n - y . sum w n, so the loop needs no d and one
  // product for d.n rather than D. (All terms are within a few Delta of 0, so
  // nothing cancels badly.)
  Vec<D> centre = Vec<D>::Zero();
  for (const Vec<D>& corner : corners) centre += corner;
  centre /= V;
  double y[D][V], yy[V] = {};
  for (int v = 0; v < V; ++v)
    for (int a = 0; a < D; ++a) {
      y[a][v] = corners[v][a] - centre[a];
      yy[v] += y[a][v] * y[a][v];
    }
  double sum_w[V] = {}, sum_qn[V] = {}, sum_dd[V] = {}, sum_offset[V] = {}, sum_q[D][V] = {}, sum_n[D][V] = {};
  const double inverse_r2 = 1.0 / (radius_ * radius_);
  const std::size_t n = neighbourhood.positions.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec<D> q = neighbourhood.positions[k] - centre;
    const Vec<D>& normal = neighbourhood.normals[k];
    const double qq = q.squaredNorm();
    const double qn = q.dot(normal);
    double dd[V], s2[V], w[V];
    for (int v = 0; v < V; ++v) dd[v] = qq + yy[v];
    for (int a = 0; a < D; ++a)
      for (int v = 0; v < V; ++v) dd[v] -= 2.0 * q[a] * y[a][v];
    const double inverse_r2_k = kWidened ? neighbourhood.inverse_r2[k] : inverse_r2;
    for (int v = 0; v < V; ++v) s2[v] = dd[v] * inverse_r2_k;
    weights_of_squared_ratios(s2, w);
    for (int v = 0; v < V; ++v) {
      sum_w[v] += w[v];
      sum_dd[v] += w[v] * dd[v];
      sum_qn[v] += w[v] * qn;
    }
    if constexpr (kCorrected)
      for (int v = 0; v < V; ++v) sum_offset[v] += w[v] * neighbourhood.offsets[k];
    for (int a = 0; a < D; ++a)
      for (int v = 0; v < V; ++v) {
        sum_q[a][v] += w[v] * q[a];
        sum_n[a][v] += w[v] * normal[a];
      }
  }
  for (int v = 0; v < V; ++v) {
    Vec<D> sum_d, sn;
    double sum_dn = sum_qn[v];
    for (int a = 0; a < D; ++a) {
      sum_d[a] = sum_q[a][v] - y[a][v] * sum_w[v];
      sn[a] = sum_n[a][v];
      sum_dn -= y[a][v] * sn[a];
    }
    out[v] = GradientFit<D>(sum_w[v], sum_d, sn, sum_dn, sum_dd[v], sum_offset[v]).solve(parameters_.min_weight);
  }
}

template <int D>
PrattFit<D> AmlsSurface<D>::pratt_fit_in(const Neighbourhood<D>& neighbourhood, const Vec<D>& p,
                                        const Vec<D>& carried) const {
  const double inverse_radius = 1.0 / radius_;
  const bool filter = parameters_.orientation_filter;
  PrattFit<D> fit;
  for (std::size_t k = 0; k < neighbourhood.positions.size(); ++k) {
    if (filter && !agrees(neighbourhood.normals[k], carried)) continue;
    const Vec<D> u = (neighbourhood.positions[k] - p) * inverse_radius;
    fit.add(u, weight_of_squared_ratio(u.squaredNorm()));
  }
  return fit;
}

template class AmlsSurface<2>;
template class AmlsSurface<3>;

}  // namespace amls
