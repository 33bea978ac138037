#include "core/resample/point_splice.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/point_index.hpp"
#include "core/util/flat_hash_map.hpp"

namespace amls {

namespace {

// How close, in h, the resampler puts two of its points at neighbouring
// vertices: across a cell's diagonal, h / sqrt(2) (the least spacing of whole
// resamples: 0.71 h on the vortex and the drag). Along a smooth curve its
// points are all about h apart, and the crowding distance of the seam (the
// closest two of R's new points) would be about h: a new point dropped for a
// kept one that near leaves a gap of two spacings. So it is at most this.
constexpr double kClosestCrossings = 0.70710678118654752;

// A new point within a held region is dropped where a kept point lies this
// near (in h): the region's own points cover it. Farther from every kept
// point it fills a hole (a part of the surface that came into the region
// without its points), and is kept by the seam's rule. A resample leaves its
// points at most about 1.41 h from their nearest neighbour, so where the
// region's own points are, a new point has one of them within this.
constexpr double kHeldCover = 1.5;

// The smallest distance between two of `positions`, if one is below `most`;
// else `most`.
template <int D>
double closest_pair(const std::vector<Vec<D>>& positions, const Vec<D>& origin, double most) {
  PointIndex<D> index;
  index.build(positions, origin, most);
  double closest2 = most * most;
  for (std::uint32_t i = 0; i < positions.size(); ++i)
    index.for_each_within(positions[i], most, [&](std::uint32_t j, const Vec<D>& q) {
      if (j != i) closest2 = std::min(closest2, (q - positions[i]).squaredNorm());
    });
  return std::sqrt(closest2);
}

// One byte per point: whether a held region holds it, asked only of the
// points `asked(i)` names (the others, and all without held regions, 0).
template <int D, typename Asked>
std::vector<std::uint8_t> held_mask(const std::vector<Vec<D>>& positions, const HeldRegions<D>& held, Asked&& asked,
                                    ThreadPool& pool) {
  std::vector<std::uint8_t> mask(positions.size(), 0);
  if (held.empty()) return mask;
  pool.parallel_for(positions.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) mask[i] = asked(i) && held.holds(positions[i]) ? 1 : 0;
  });
  return mask;
}

}  // namespace

template <int D>
SpliceCounts splice_points(PointSet<D>& points, std::vector<float>* strain, const PointSet<D>& fresh,
                           const SpliceRings& rings, const HeldRegions<D>& held, const Grid<D>& grid,
                           ThreadPool& pool) {
  const double h = grid.spacing();
  auto old_ring = [&](std::size_t i) { return rings.old_ring.empty() ? std::uint8_t{0} : rings.old_ring[i]; };
  auto fresh_ring = [&](std::size_t k) { return rings.fresh_ring.empty() ? std::uint8_t{0} : rings.fresh_ring[k]; };
  auto nearest_vertex = [&](const Vec<D>& p) {
    IVec<D> v;
    for (int a = 0; a < D; ++a) v[a] = static_cast<std::int64_t>(std::floor((p[a] - grid.origin()[a]) / h + 0.5));
    return v;
  };
  const std::uint8_t farthest =
      rings.fill ? rings.walked : rings.region;  // the farthest ring whose new points are kept
  // Only an old point of R would go, and only a new point within `farthest` would stay.
  const std::vector<std::uint8_t> old_held = held_mask<D>(
      points.positions, held, [&](std::size_t i) { return old_ring(i) <= rings.region; }, pool);
  const std::vector<std::uint8_t> fresh_held = held_mask<D>(
      fresh.positions, held, [&](std::size_t k) { return fresh_ring(k) <= farthest; }, pool);
  SpliceCounts counts;
  FlatHashMap<std::uint8_t> claimed;
  std::vector<Vec<D>> seam_points;
  PointSet<D> out;
  std::vector<float> out_strain;
  out.reserve(points.size());
  if (strain) out_strain.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (old_ring(i) <= rings.region) {
      if (!old_held[i]) {
        ++counts.replaced;
        continue;
      }
      ++counts.held;
    }
    // A kept point one ring beyond the strip can still be within h of a new point.
    if (old_ring(i) <= rings.walked + 1) {
      claimed.try_emplace(Grid<D>::key(nearest_vertex(points.positions[i])));
      seam_points.push_back(points.positions[i]);
    }
    out.add(points.positions[i], points.normals[i], points.on_rim(i));
    if (strain) out_strain.push_back((*strain)[i]);
  }
  double crowding = 0.0;  // no kept point near: nothing to crowd
  if (!seam_points.empty()) {
    std::vector<Vec<D>> in_region;
    for (std::size_t k = 0; k < fresh.size(); ++k)
      if (fresh_ring(k) <= rings.region && !fresh_held[k]) in_region.push_back(fresh.positions[k]);
    crowding = closest_pair<D>(in_region, grid.origin(), kClosestCrossings * h);
  }
  PointIndex<D> seam_index;
  seam_index.build(seam_points, grid.origin(), kHeldCover * h);  // as wide as the farthest query
  // Whether a kept point near the seam lies closer to q than `radius`.
  auto kept_within = [&](const Vec<D>& q, double radius) {
    bool near = false;
    seam_index.for_each_within(q, radius, [&](std::uint32_t, const Vec<D>& p) {
      near = near || (p - q).squaredNorm() < radius * radius;
    });
    return near;
  };
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    if (fresh_ring(k) > farthest) continue;
    const Vec<D>& q = fresh.positions[k];
    if (fresh_held[k] && kept_within(q, kHeldCover * h)) {
      ++counts.covered;
      continue;
    }
    if (claimed.find(Grid<D>::key(nearest_vertex(q))) || kept_within(q, crowding)) {
      ++counts.dropped_at_seam;
      continue;
    }
    out.add(q, fresh.normals[k], fresh.on_rim(k));
    if (strain) out_strain.push_back(0.0F);
    ++(fresh_ring(k) <= rings.region ? counts.inserted : counts.filled_at_seam);
  }
  points = std::move(out);
  if (strain) *strain = std::move(out_strain);
  return counts;
}

template SpliceCounts splice_points<2>(PointSet<2>&, std::vector<float>*, const PointSet<2>&, const SpliceRings&,
                                       const HeldRegions<2>&, const Grid<2>&, ThreadPool&);
template SpliceCounts splice_points<3>(PointSet<3>&, std::vector<float>*, const PointSet<3>&, const SpliceRings&,
                                       const HeldRegions<3>&, const Grid<3>&, ThreadPool&);

}  // namespace amls
