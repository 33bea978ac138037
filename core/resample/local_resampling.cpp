#include "core/resample/local_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/geometry/point_index.hpp"
#include "core/resample/point_splice.hpp"
#include "core/resample/region_rings.hpp"
#include "core/surface/local_support.hpp"
#include "core/util/flat_hash_map.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

// A region cell is this many h wide: a brick of the vertex field.
constexpr double kCellInH = 4.0;
// How many supports away from a vertex F there reads a point's position and
// carried normal: F reads the points within Delta_i (1), their offsets are
// limited over Delta_i / 2 (1.5) from offsets smoothed over Delta_i (2.5),
// each of which is F at a point (3.5) from its neighbours' pseudo-normals,
// whose Pratt fits read their neighbours (4.5). In 2D (no offsets) 2 would
// do; one reach for both keeps the rings simple.
constexpr double kSupportHops = 4.5;
// A point's ring (core/resample/region_rings.hpp); beyond the rings measured, kOutside.
constexpr std::uint8_t kOutside = RegionRings<2>::kOutside;

// The cells of the points over the strain limit, grown cell by cell into the
// neighbouring cells whose points passed `grow_above` of it (see
// LocalResampleOptions); `over_limit` counts the points over the limit.
template <int D>
std::vector<IVec<D>> flag_cells(const PointSet<D>& points, const std::vector<float>& strain, const Grid<D>& cells,
                                const LocalResampleOptions& options, std::size_t& over_limit) {
  const double limit = options.strain_limit;
  const double warm_limit = options.grow_above * limit;
  std::vector<IVec<D>> flagged;
  FlatHashMap<std::uint8_t> flagged_keys;
  FlatHashMap<std::uint8_t> warm_keys;
  over_limit = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(strain[i] > warm_limit)) continue;
    const IVec<D> c = cells.cell_of(points.positions[i]);
    if (!(strain[i] > limit)) {
      warm_keys.try_emplace(Grid<D>::key(c));
      continue;
    }
    ++over_limit;
    if (flagged_keys.try_emplace(Grid<D>::key(c)).second) flagged.push_back(c);
  }
  if (flagged.empty()) return flagged;
  for (std::size_t k = 0; k < flagged.size(); ++k) {
    const IVec<D> c = flagged[k];  // a copy: push_back may move the vector
    for_each_index_in_box<D>(c.array() - 1, c.array() + 1, [&](const IVec<D>& n) {
      const std::uint64_t key = Grid<D>::key(n);
      if (warm_keys.find(key) && flagged_keys.try_emplace(key).second) flagged.push_back(n);
    });
  }
  return flagged;
}

}  // namespace

template <int D>
LocalResampler<D>::LocalResampler(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant)
    : grid_(grid), parameters_(parameters), variant_(variant), cell_size_(kCellInH * grid.spacing()) {}

template <int D>
LocalResampleStats LocalResampler<D>::resample(PointSet<D>& points, std::vector<float>& strain, ThreadPool& pool,
                                               const HeldRegions<D>& held) {
  if (strain.size() != points.size())
    throw std::invalid_argument("local resampling: " + std::to_string(points.size()) + " points but " +
                                std::to_string(strain.size()) + " strains");
  LocalResampleStats stats;
  Stopwatch clock;
  const double h = grid_.spacing();
  const double delta = parameters_.radius_factor * h;
  const Grid<D> cells(grid_.origin(), cell_size_);
  std::size_t flagged_points = 0;
  const std::vector<IVec<D>> flagged = flag_cells<D>(points, strain, cells, options_, flagged_points);
  stats.flagged_cells = flagged.size();
  if (flagged.empty()) return stats;

  auto rings_for = [&](double distance) { return static_cast<std::int64_t>(std::ceil(distance / cell_size_)); };
  const std::int64_t region = rings_for(delta);  // R: the flagged cells grown by Delta
  const std::int64_t walked = region + rings_for(2.0 * h);
  // The points F in the walked cells reads, for supports up to `widest`: the
  // walks' vertices lie within 2 h of their points.
  auto support_for = [&](double widest) { return walked + rings_for(kSupportHops * widest + 2.0 * h); };
  // With widened supports, a point p_k that F in the walked cells reads
  // lies within 3.5 W + 2 h + max(W, Delta_k) of them for the widest Delta_i
  // W it meets before (see below); Delta_i is measured on the points within
  // kSupportMeasureReach h of p_k.
  const double most = kMostWidening * delta;
  auto may_read = [&](double widest, double own) {
    return walked + rings_for((kSupportHops - 1.0) * widest + 2.0 * h + std::max(widest, own));
  };
  const bool widen = parameters_.widen_support;
  const std::int64_t most_reach =
      widen ? may_read(most, most) + rings_for(kSupportMeasureReach * h) : support_for(delta);
  // With every point flagged (a start, or a whole-surface resample) every
  // point is in R: no rings to grow.
  std::optional<RegionRings<D>> rings;
  if (flagged_points != points.size()) rings.emplace(cells, flagged, most_reach);
  auto ring_of = [&](const Vec<D>& p) { return rings ? rings->ring(p) : std::uint8_t{0}; };
  // Each point's ring, measured as the rings grow, and the points within
  // them. The first growth looks every point up; later ones only the points
  // without a ring then whose cells the rings can reach (`pending`, listed
  // at the second growth).
  std::vector<std::uint8_t> ring(points.size(), rings ? kOutside : std::uint8_t{0});
  std::vector<std::uint32_t> pending;
  int growths = 0;
  std::vector<std::uint32_t> near;  // in the points' order
  auto grow_rings = [&](std::int64_t reach) {
    rings->grow_to(reach);
    if (growths++ == 0) {
      pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) ring[i] = rings->ring(points.positions[i]);
      });
    } else {
      if (growths == 2) {
        std::vector<std::uint8_t> reachable(points.size());
        pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
          for (std::size_t i = begin; i < end; ++i)
            reachable[i] = ring[i] == kOutside && rings->may_reach(points.positions[i]);
        });
        for (std::uint32_t i = 0; i < points.size(); ++i)
          if (reachable[i]) pending.push_back(i);
      }
      pool.parallel_for(pending.size(), [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t k = begin; k < end; ++k)
          if (ring[pending[k]] == kOutside) ring[pending[k]] = rings->ring(points.positions[pending[k]]);
      });
    }
    near.clear();
    for (std::uint32_t i = 0; i < points.size(); ++i)
      if (ring[i] != kOutside) near.push_back(i);
    stats.rings_seconds += clock.lap();
  };
  // Those of the points `ids` within `reach`, in their order.
  auto points_within = [&](std::int64_t reach, const std::vector<std::uint32_t>& ids) {
    PointSet<D> out;
    for (const std::uint32_t i : ids)
      if (ring[i] <= reach) out.add(points.positions[i], points.normals[i], points.on_rim(i));
    return out;
  };

  AmlsSurface<D> surface(grid_, parameters_);
  if (!rings) {
    surface.set_points(points);
  } else if (!widen) {
    grow_rings(support_for(delta));
    surface.set_points(points_within(support_for(delta), near));
  } else {
    // Each Delta_i as the whole surface measures it, and the support grown
    // for the widest Delta_i that F in the walked cells reads. F reads a
    // point through a chain of hops (kSupportHops: 4.5 supports in all), each
    // no longer than the support of one of its ends. While every point met
    // has Delta_i <= W, the chain stays within 3.5 W + 2 h of the walked
    // cells before its last hop, so any point p_k it meets lies within
    // 3.5 W + 2 h + max(W, Delta_k) of them: W holds when each point that
    // near has Delta_k <= W. Starting from W = Delta, Delta_i is measured on
    // the points that may be that near for any Delta_k up to the most
    // allowed, and on those within the measure's reach of them (so that it
    // is exact); W grows to the widest Delta_k that is that near, and the
    // measure grows with it when its rings do. So the rings reach only as
    // far as the supports near R ask, not as far as the widest allowed.
    double widest = delta;
    std::int64_t measured = -1;  // Delta_i is exact for the points within these rings
    std::vector<double> radii;
    for (;;) {
      if (may_read(widest, most) > measured) {
        measured = may_read(widest, most);
        grow_rings(measured + rings_for(kSupportMeasureReach * h));
        std::vector<Vec<D>> positions(near.size());
        for (std::size_t k = 0; k < near.size(); ++k) positions[k] = points.positions[near[k]];
        radii = widened_support_radii<D>(positions, delta, h, pool);
        if (radii.empty()) radii.assign(near.size(), delta);
      }
      double wider = widest;
      for (std::size_t k = 0; k < near.size(); ++k)
        if (ring[near[k]] <= may_read(widest, radii[k])) wider = std::max(wider, radii[k]);
      stats.radii_seconds += clock.lap();
      if (wider <= widest) break;
      widest = wider;
    }
    const std::int64_t support = support_for(widest);
    std::vector<double> support_radii;
    for (std::size_t k = 0; k < near.size(); ++k)
      if (ring[near[k]] <= support) support_radii.push_back(radii[k]);
    surface.set_points(points_within(support, near), std::move(support_radii));
  }
  stats.region_cells = rings ? rings->cells_within(region) : flagged.size();
  stats.support = surface.points().size();
  surface.hash_points(pool);
  stats.normals = surface.update_normals(pool);
  stats.normals_seconds = stats.rings_seconds + stats.radii_seconds + clock.lap();

  // The whole surface's walks (with widened supports, over the widened
  // points' discs too) that reach R.
  std::vector<Vec<D>> walk = Resampler<D>::walk_positions(surface, pool);
  walk.erase(std::remove_if(walk.begin(), walk.end(), [&](const Vec<D>& p) { return ring_of(p) > walked; }),
             walk.end());
  resampler_.update_function(surface, walk, pool);
  stats.function_seconds = clock.lap();

  const PointSet<D> fresh = resampler_.resample(surface, variant_, pool);
  stats.resample = resampler_.stats();
  std::vector<std::uint8_t> fresh_ring(fresh.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) fresh_ring[k] = ring_of(fresh.positions[k]);
  const SpliceRings where{ring, fresh_ring, static_cast<std::uint8_t>(region), static_cast<std::uint8_t>(walked),
                          options_.fill_seam};
  const SpliceCounts spliced = splice_points<D>(points, &strain, fresh, where, held, grid_, pool);
  stats.replaced = spliced.replaced;
  stats.held = spliced.held;
  stats.inserted = spliced.inserted;
  stats.filled_at_seam = spliced.filled_at_seam;
  stats.dropped_at_seam = spliced.dropped_at_seam + spliced.covered;
  stats.resample_seconds = clock.lap();
  return stats;
}

template class LocalResampler<2>;
template class LocalResampler<3>;

}  // namespace amls
