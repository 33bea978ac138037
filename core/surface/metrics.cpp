#include "core/surface/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/math/root_finding.hpp"
#include "core/surface/block_sample.hpp"
#include "core/surface/spacing_band.hpp"
#include "core/util/block_join.hpp"

namespace amls {

namespace {

// The squared distance from p to the nearest of `positions` (indexed by
// `index`) other than `skip`, searching ever wider from `radius`. Once the
// search box would hold more index cells than there are points, every point
// is scanned instead: a lone far point would otherwise make the boxes huge.
template <int D>
double nearest_squared(const PointIndex<D>& index, const std::vector<Vec<D>>& positions, const Vec<D>& p,
                       double radius, std::uint32_t skip) {
  double best2 = std::numeric_limits<double>::infinity();
  auto consider = [&](std::uint32_t id, const Vec<D>& q) {
    if (id != skip) best2 = std::min(best2, (q - p).squaredNorm());
  };
  for (; !std::isfinite(best2); radius *= 4.0) {
    if (std::pow(2.0 * radius / index.cell_size(), D) > static_cast<double>(positions.size())) {
      for (std::size_t j = 0; j < positions.size(); ++j) consider(static_cast<std::uint32_t>(j), positions[j]);
      break;
    }
    index.for_each_within(p, radius, consider);
  }
  return best2;
}

// The cells of the indexes that nearest-neighbour searches use, in h, and
// the search's first radius. Cells twice the radius hold four times the
// points (in 2D: twice) of cells as wide as it, but a search visits at most
// 2^D of them instead of 3^D, for about the same points read; and a dense
// cell table over a million points' box is 8 times smaller (in 3D: 30 MB,
// not 240), so the index is quicker to build.
constexpr double kSearchCell = 4.0;
constexpr double kSearchRadius = 2.0;

// The nearest-neighbour distance in h of points pick(0), ..., pick(count - 1)
// to the others, on the pool.
template <int D, typename Pick>
std::vector<double> nearest_spacings_of(const PointSet<D>& points, double h, std::size_t count, Pick pick,
                                        ThreadPool& pool) {
  if (points.size() < 2) return {};
  PointIndex<D> index;
  index.build(points.positions, Vec<D>::Zero(), kSearchCell * h, pool);
  std::vector<double> nearest(count);
  pool.parallel_for(count, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = pick(k);
      nearest[k] =
          std::sqrt(nearest_squared(index, points.positions, points.positions[i], kSearchRadius * h,
                                    static_cast<std::uint32_t>(i))) /
          h;
    }
  });
  return nearest;
}

}  // namespace

template <int D>
std::vector<double> nearest_neighbour_spacing_per_point(const PointSet<D>& points, double h, ThreadPool& pool) {
  return nearest_spacings_of(points, h, points.size(), [](std::size_t k) { return k; }, pool);
}

template <int D>
std::vector<double> nearest_neighbour_spacing_per_point(const PointSet<D>& points, double h) {
  ThreadPool one(1);
  return nearest_neighbour_spacing_per_point(points, h, one);
}

template <int D>
std::vector<double> nearest_neighbour_spacings(const PointSet<D>& points, double h) {
  std::vector<double> nearest = nearest_neighbour_spacing_per_point(points, h);
  std::sort(nearest.begin(), nearest.end());
  return nearest;
}

SpacingStats spacing_stats_of(const std::vector<double>& sorted_spacings) {
  SpacingStats s;
  if (sorted_spacings.empty()) return s;
  s.min = sorted_spacings.front();
  s.max = sorted_spacings.back();
  s.median = sorted_spacings[sorted_spacings.size() / 2];
  return s;
}

template <int D>
SpacingStats spacing_stats(const PointSet<D>& points, double h) {
  return spacing_stats_of(nearest_neighbour_spacings(points, h));
}

namespace {

// A large frame's spacing sample is the points of a few blocks of the grid
// of side kSampleBlock h: about 50 points of a surface sampled at h each, so
// a sample of 100,000 is spread over a couple of thousand places. A block is
// sampled when a hash of its coordinates says so, the same for any thread
// count and point order.
constexpr double kSampleBlock = 8.0;

template <int D>
void summarise(std::vector<double>& spacings, SpacingSummary& s) {
  s.measured = spacings.size();
  if (spacings.empty()) return;
  // No full sort: the median's place, and one pass for the rest.
  const auto middle = spacings.begin() + static_cast<std::ptrdiff_t>(spacings.size() / 2);
  std::nth_element(spacings.begin(), middle, spacings.end());
  s.h.median = *middle;
  s.h.min = s.h.max = spacings.front();
  for (const double d : spacings) {
    s.h.min = std::min(s.h.min, d);
    s.h.max = std::max(s.h.max, d);
    s.below += d < kSpacingBandLow ? 1 : 0;
    s.above += d > kSpacingBandHigh ? 1 : 0;
  }
}

// The nearest distances in h from the points of `from` in sampled blocks
// (one block in `every`) to the points of `to` (with `same`, `from` is `to`
// and a point's distance is to its nearest other point), in from's order.
// Only the points of `to` within `reach` = 2h of a sampled block (the
// candidates) are indexed, found in one light pass over the set: a sampled
// point's nearest within reach is then among them, so its distance is exact.
// A sampled point with no candidate within reach (a gap wider than 2h) is
// measured against every point of `to`, with an index of them all.
template <int D>
std::vector<double> block_sample_nearest(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, bool same,
                                         double h, std::uint64_t every, ThreadPool& pool) {
  const double reach = kSearchRadius * h;
  const BlockSample<D> blocks(kSampleBlock * h, every);
  using Placed = typename BlockSample<D>::Placed;
  const std::vector<Placed> candidates = blocks.placed(to, reach, pool);
  std::vector<Vec<D>> positions(candidates.size());
  pool.parallel_for(candidates.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) positions[k] = to[candidates[k].id];
  });
  // The measured points: with `same`, the candidates inside sampled blocks
  // (named by their place among the candidates, to skip themselves), else
  // those of `from`.
  std::vector<Placed> measured;
  if (same) {
    measured.reserve(candidates.size());
    for (std::size_t k = 0; k < candidates.size(); ++k)
      if (candidates[k].place == BlockPlace::inside) measured.push_back({static_cast<std::uint32_t>(k), BlockPlace::inside});
  } else {
    for (const Placed& p : blocks.placed(from, 0.0, pool))
      if (p.place == BlockPlace::inside) measured.push_back(p);
  }
  auto at = [&](const Placed& m) -> const Vec<D>& { return same ? positions[m.id] : from[m.id]; };
  PointIndex<D> index;
  index.build(positions, Vec<D>::Zero(), kSearchCell * h, pool);
  // A NaN marks the points without a candidate within reach.
  std::vector<double> nearest(measured.size());
  pool.parallel_for(measured.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t self = same ? measured[k].id : std::numeric_limits<std::uint32_t>::max();
      const Vec<D>& p = at(measured[k]);
      double best2 = std::numeric_limits<double>::infinity();
      index.for_each_within(p, reach, [&](std::uint32_t id, const Vec<D>& q) {
        if (id != self) best2 = std::min(best2, (q - p).squaredNorm());
      });
      nearest[k] = std::isfinite(best2) ? std::sqrt(best2) / h : std::numeric_limits<double>::quiet_NaN();
    }
  });
  std::vector<std::size_t> far;
  for (std::size_t k = 0; k < nearest.size(); ++k)
    if (std::isnan(nearest[k])) far.push_back(k);
  if (!far.empty()) {
    PointIndex<D> whole;
    whole.build(to, Vec<D>::Zero(), kSearchCell * h, pool);
    pool.parallel_for(far.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t f = begin; f < end; ++f) {
        const Placed& m = measured[far[f]];
        const std::uint32_t self = same ? candidates[m.id].id : std::numeric_limits<std::uint32_t>::max();
        nearest[far[f]] = std::sqrt(nearest_squared(whole, to, at(m), kSearchRadius * h, self)) / h;
      }
    });
  }
  return nearest;
}

}  // namespace

template <int D>
SpacingSummary spacing_summary(const PointSet<D>& points, double h, std::size_t max_measured, ThreadPool& pool) {
  SpacingSummary s;
  s.of = points.size();
  if (points.size() < 2) return s;
  std::vector<double> spacings;
  if (points.size() > max_measured) {
    const std::uint64_t every = (points.size() + max_measured - 1) / std::max<std::size_t>(max_measured, 1);
    spacings = block_sample_nearest(points.positions, points.positions, true, h, every, pool);
  }
  // A small set, or a sample that fell on no point (a few points far apart): every point.
  if (spacings.empty())
    spacings = nearest_spacings_of(points, h, points.size(), [](std::size_t k) { return k; }, pool);
  summarise<D>(spacings, s);
  return s;
}

namespace {

// Nearest distances are summed in chunks of a fixed size and the chunks in
// order, so that the mean has the same bits for any thread count.
constexpr std::size_t kDistanceChunk = 4096;

}  // namespace

template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h,
                                     ThreadPool& pool) {
  DistanceStats s;
  if (from.empty()) return s;
  if (to.empty()) throw std::invalid_argument("nearest distances: the set to measure against is empty");
  PointIndex<D> index;
  index.build(to, to.front(), kSearchCell * h, pool);
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const std::size_t chunks = (from.size() + kDistanceChunk - 1) / kDistanceChunk;
  std::vector<double> sums(chunks, 0.0), maxima(chunks, 0.0);
  pool.parallel_for(chunks, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t c = begin; c < end; ++c)
      for (std::size_t i = c * kDistanceChunk; i < std::min(from.size(), (c + 1) * kDistanceChunk); ++i) {
        const double d = std::sqrt(nearest_squared(index, to, from[i], kSearchRadius * h, kNone)) / h;
        sums[c] += d;
        maxima[c] = std::max(maxima[c], d);
      }
  });
  double sum = 0.0;
  for (std::size_t c = 0; c < chunks; ++c) {
    sum += sums[c];
    s.max = std::max(s.max, maxima[c]);
  }
  s.count = from.size();
  s.mean = sum / static_cast<double>(from.size());
  return s;
}

template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h,
                                     std::size_t max_measured, ThreadPool& pool) {
  if (max_measured == 0 || from.size() <= max_measured) return nearest_distance_stats(from, to, h, pool);
  if (to.empty()) throw std::invalid_argument("nearest distances: the set to measure against is empty");
  const std::vector<double> nearest =
      block_sample_nearest(from, to, false, h, (from.size() + max_measured - 1) / max_measured, pool);
  // A sample that fell on no point (a few points far apart): every point.
  if (nearest.empty()) return nearest_distance_stats(from, to, h, pool);
  DistanceStats s;
  double sum = 0.0;  // in from's order, whatever the thread count
  for (const double d : nearest) {
    sum += d;
    s.max = std::max(s.max, d);
  }
  s.count = nearest.size();
  s.mean = sum / static_cast<double>(nearest.size());
  return s;
}

template <int D>
DistanceStats nearest_distance_stats(const std::vector<Vec<D>>& from, const std::vector<Vec<D>>& to, double h) {
  ThreadPool one(1);
  return nearest_distance_stats(from, to, h, one);
}

template SpacingStats spacing_stats<2>(const PointSet<2>&, double);
template SpacingStats spacing_stats<3>(const PointSet<3>&, double);
template std::vector<double> nearest_neighbour_spacings<2>(const PointSet<2>&, double);
template std::vector<double> nearest_neighbour_spacings<3>(const PointSet<3>&, double);
template std::vector<double> nearest_neighbour_spacing_per_point<2>(const PointSet<2>&, double);
template std::vector<double> nearest_neighbour_spacing_per_point<3>(const PointSet<3>&, double);
template std::vector<double> nearest_neighbour_spacing_per_point<2>(const PointSet<2>&, double, ThreadPool&);
template std::vector<double> nearest_neighbour_spacing_per_point<3>(const PointSet<3>&, double, ThreadPool&);
template DistanceStats nearest_distance_stats<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double);
template DistanceStats nearest_distance_stats<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double);
template DistanceStats nearest_distance_stats<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double,
                                                 ThreadPool&);
template DistanceStats nearest_distance_stats<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double,
                                                 ThreadPool&);
template DistanceStats nearest_distance_stats<2>(const std::vector<Vec<2>>&, const std::vector<Vec<2>>&, double,
                                                 std::size_t, ThreadPool&);
template DistanceStats nearest_distance_stats<3>(const std::vector<Vec<3>>&, const std::vector<Vec<3>>&, double,
                                                 std::size_t, ThreadPool&);
template SpacingSummary spacing_summary<2>(const PointSet<2>&, double, std::size_t, ThreadPool&);
template SpacingSummary spacing_summary<3>(const PointSet<3>&, double, std::size_t, ThreadPool&);

namespace {

// The radii at which F changes sign along the ray centre + r u, r in [r_lo, r_hi],
// sampled every `step` and refined by the bracketed root finder.
template <int D>
std::vector<double> crossings_along_ray(const AmlsSurface<D>& surface, const Vec<D>& center, const Vec<D>& u,
                                        double r_lo, double r_hi, double step) {
  std::vector<double> roots;
  auto value_at = [&](double r) -> std::optional<RootSample> {
    const Evaluation<D> e = surface.evaluate(center + r * u);
    if (!e.defined) return std::nullopt;
    return RootSample{e.value, e.gradient.dot(u)};
  };
  std::optional<double> previous;
  double previous_r = r_lo;
  RootOptions options;
  options.tolerance = 1e-12 * step;
  for (double r = r_lo; r <= r_hi + 0.5 * step; r += step) {
    const std::optional<RootSample> sample = value_at(r);
    const std::optional<double> f = sample ? std::optional<double>(sample->value) : std::nullopt;
    if (f && previous && ((*f >= 0.0) != (*previous >= 0.0))) {
      const RootResult root = find_root(value_at, previous_r, r, *previous, *f, options);
      roots.push_back(root.ok ? root.t : previous_r + (r - previous_r) * *previous / (*previous - *f));
    }
    previous = f;
    previous_r = r;
  }
  return roots;
}

// The range of distances from `center` that the zero set can reach: F is
// undefined farther than Delta from every point.
template <int D>
std::pair<double, double> radial_range(const AmlsSurface<D>& surface, const Vec<D>& center) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Vec<D>& p : surface.points().positions) {
    const double r = (p - center).norm();
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  return {std::max(0.0, lo - surface.radius()), hi + surface.radius()};
}

// Along a ray from the centre, a closed surface around the centre is crossed
// an odd number of times; the inside is [0, r1] u [r2, r3] u ... In 2D the
// paper's test wants one closed curve: exactly one crossing.
enum class RayRule { exactly_once, odd };

template <int D, typename Direction, typename Accumulate>
RayScan scan_rays(const AmlsSurface<D>& surface, const Vec<D>& center, std::size_t rays, RayRule rule,
                  ThreadPool& pool, Direction&& direction, Accumulate&& accumulate) {
  RayScan scan;
  scan.rays = rays;
  if (surface.points().empty()) {
    scan.closed = false;
    scan.bad_rays = rays;
    scan.reason = "the point set is empty";
    return scan;
  }
  // Named copies, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
  const auto range = radial_range(surface, center);
  const double r_lo = range.first, r_hi = range.second;
  const double step = 0.5 * surface.grid().spacing();
  // Rays are scanned in parallel and accumulated in order, so sums do not
  // depend on the thread count.
  std::vector<std::vector<double>> roots_of(rays);
  pool.parallel_for(rays, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k)
      roots_of[k] = crossings_along_ray(surface, center, direction(k), r_lo, r_hi, step);
  });
  std::size_t none = 0, wrong = 0;
  for (const std::vector<double>& roots : roots_of) {
    const bool good = rule == RayRule::exactly_once ? roots.size() == 1 : roots.size() % 2 == 1;
    if (good) {
      accumulate(roots);
    } else {
      (roots.empty() ? none : wrong) += 1;
    }
  }
  scan.bad_rays = none + wrong;
  scan.closed = scan.bad_rays == 0;
  if (!scan.closed)
    scan.reason = std::to_string(none) + " of " + std::to_string(rays) + " rays miss the surface and " +
                  std::to_string(wrong) +
                  (rule == RayRule::exactly_once ? " cross it more than once" : " cross it an even number of times");
  return scan;
}

// The integral of r^(D-1) dr over the inside set of a ray ([0, r1] u [r2, r3] u ...),
// and over its symmetric difference with [0, radius].
template <int D>
std::pair<double, double> radial_measures(const std::vector<double>& roots, double radius) {
  auto primitive = [](double r) { return std::pow(r, D) / D; };
  double inside = 0.0, difference = 0.0;
  std::vector<double> breaks{0.0};
  breaks.insert(breaks.end(), roots.begin(), roots.end());
  for (std::size_t i = 0; i + 1 < breaks.size(); i += 2) inside += primitive(breaks[i + 1]) - primitive(breaks[i]);
  // Walk the merged breakpoints; membership flips at each root, and the
  // sphere's at `radius`.
  std::vector<std::pair<double, int>> events;
  for (double r : roots) events.push_back({r, 0});
  events.push_back({radius, 1});
  std::sort(events.begin(), events.end());
  bool in_shape = true, in_sphere = true;
  double previous = 0.0;
  for (const auto& [r, which] : events) {
    if (in_shape != in_sphere) difference += primitive(r) - primitive(previous);
    (which == 0 ? in_shape : in_sphere) = !(which == 0 ? in_shape : in_sphere);
    previous = r;
  }
  return {inside, difference};
}

}  // namespace

CircleError circle_l1_error(const AmlsSurface<2>& surface, const Vec<2>& center, double radius, ThreadPool& pool,
                            std::size_t rays) {
  CircleError out;
  const double dtheta = 2.0 * std::numbers::pi / static_cast<double>(rays);
  auto direction = [&](std::size_t k) {
    const double theta = (static_cast<double>(k) + 0.5) * dtheta;
    return Vec<2>(std::cos(theta), std::sin(theta));
  };
  // Area between the curves in polar form: integral of |r^2 - R^2| / 2 d theta.
  out.scan = scan_rays<2>(surface, center, rays, RayRule::exactly_once, pool, direction, [&](const std::vector<double>& roots) {
    out.l1 += radial_measures<2>(roots, radius).second * dtheta;
  });
  return out;
}

SphereError sphere_volume_error(const AmlsSurface<3>& surface, const Vec<3>& center, double radius, ThreadPool& pool,
                                std::size_t rays) {
  SphereError out;
  const double solid_angle = 4.0 * std::numbers::pi / static_cast<double>(rays);
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  auto direction = [&](std::size_t k) {
    const double z = 1.0 - (2.0 * static_cast<double>(k) + 1.0) / static_cast<double>(rays);
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * static_cast<double>(k);
    return Vec<3>(s * std::cos(phi), s * std::sin(phi), z);
  };
  // Volumes in spherical form: integrals of r^2 dr d omega.
  out.scan = scan_rays<3>(surface, center, rays, RayRule::odd, pool, direction, [&](const std::vector<double>& roots) {
    const auto [inside, difference] = radial_measures<3>(roots, radius);
    out.volume += inside * solid_angle;
    out.symmetric_difference += difference * solid_angle;
  });
  out.exact_volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  return out;
}

}  // namespace amls
