#include "core/resample/local_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/geometry/point_index.hpp"
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
// A point's ring: the Chebyshev distance, in region cells, from its cell to
// the nearest flagged cell; beyond the rings measured, kOutside.
constexpr std::uint8_t kOutside = std::numeric_limits<std::uint8_t>::max();

template <int D>
std::int64_t chebyshev(const IVec<D>& a, const IVec<D>& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// The rings around the flagged cells, out to `reach`, with a box that holds them all for a quick rejection.
template <int D>
class Rings {
 public:
  Rings(const Grid<D>& cells, const std::vector<IVec<D>>& flagged, std::int64_t reach) : cells_(cells) {
    lo_ = hi_ = flagged.front();
    for (const IVec<D>& f : flagged) {
      lo_ = lo_.cwiseMin(f);
      hi_ = hi_.cwiseMax(f);
      for_each_index_in_box<D>(f.array() - reach, f.array() + reach, [&](const IVec<D>& c) {
        const auto ring = static_cast<std::uint8_t>(chebyshev<D>(c, f));
        auto [value, inserted] = ring_of_.try_emplace(Grid<D>::key(c));
        *value = inserted ? ring : std::min(*value, ring);
      });
    }
    lo_.array() -= reach;
    hi_.array() += reach;
  }

  std::uint8_t ring(const Vec<D>& p) const {
    const IVec<D> c = cells_.cell_of(p);
    if ((c.array() < lo_.array()).any() || (c.array() > hi_.array()).any()) return kOutside;
    const std::uint8_t* ring = ring_of_.find(Grid<D>::key(c));
    return ring ? *ring : kOutside;
  }
  std::size_t cells_within(std::uint8_t ring) const {
    std::size_t n = 0;
    ring_of_.for_each([&](std::uint64_t, const std::uint8_t& r) { n += r <= ring ? 1 : 0; });
    return n;
  }

 private:
  Grid<D> cells_;
  IVec<D> lo_, hi_;
  FlatHashMap<std::uint8_t> ring_of_;
};

// How close, in h, the resampler puts two of its points at neighbouring
// vertices: across a cell's diagonal, h / sqrt(2) (the least spacing of whole
// resamples: 0.71 h on the vortex and the drag). Along a smooth curve its
// points are all about h apart, and the crowding distance of the seam (the
// closest two of R's new points) would be about h: a new point dropped for a
// kept one that near leaves a gap of two spacings. So it is at most this.
constexpr double kClosestCrossings = 0.70710678118654752;

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

// Replaces the old points of R (ring <= region) by the new ones there and,
// with `fill`, adds the new ones of the strip around R (ring <= walked) where
// they fill the seam. A new point is dropped where a kept point claims its
// vertex (its nearest: HAVECLOSEPOINT between old and new) or lies closer
// than the resampler lets its own points come (`crowding`). Without the strip,
// the kept points near R, stretched up to the strain limit, can lie more than
// a spacing away from R's new points.
template <int D>
void splice(PointSet<D>& points, std::vector<float>& strain, const std::vector<std::uint8_t>& ring,
            const PointSet<D>& fresh, const std::vector<std::uint8_t>& fresh_ring, std::uint8_t region,
            std::uint8_t walked, bool fill, const Grid<D>& grid, LocalResampleStats& stats) {
  const double h = grid.spacing();
  auto nearest_vertex = [&](const Vec<D>& p) {
    IVec<D> v;
    for (int a = 0; a < D; ++a) v[a] = static_cast<std::int64_t>(std::floor((p[a] - grid.origin()[a]) / h + 0.5));
    return v;
  };
  FlatHashMap<std::uint8_t> claimed;
  std::vector<Vec<D>> seam_points;
  PointSet<D> out;
  std::vector<float> out_strain;
  out.reserve(points.size());
  out_strain.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (ring[i] <= region) {
      ++stats.replaced;
      continue;
    }
    // A kept point one ring beyond the strip can still be within h of a new point.
    if (ring[i] <= walked + 1) {
      claimed.try_emplace(Grid<D>::key(nearest_vertex(points.positions[i])));
      seam_points.push_back(points.positions[i]);
    }
    out.add(points.positions[i], points.normals[i]);
    out_strain.push_back(strain[i]);
  }
  double crowding = 0.0;  // no kept point near: nothing to crowd
  if (!seam_points.empty()) {
    std::vector<Vec<D>> in_region;
    for (std::size_t k = 0; k < fresh.size(); ++k)
      if (fresh_ring[k] <= region) in_region.push_back(fresh.positions[k]);
    crowding = closest_pair<D>(in_region, grid.origin(), kClosestCrossings * h);
  }
  PointIndex<D> seam_index;
  seam_index.build(seam_points, grid.origin(), h);
  auto crowds = [&](const Vec<D>& q) {
    bool near = false;
    seam_index.for_each_within(q, crowding, [&](std::uint32_t, const Vec<D>& p) {
      near = near || (p - q).squaredNorm() < crowding * crowding;
    });
    return near;
  };
  const std::uint8_t farthest = fill ? walked : region;  // the farthest ring whose new points are kept
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    if (fresh_ring[k] > farthest) continue;
    const Vec<D>& q = fresh.positions[k];
    if (claimed.find(Grid<D>::key(nearest_vertex(q))) || crowds(q)) {
      ++stats.dropped_at_seam;
      continue;
    }
    out.add(q, fresh.normals[k]);
    out_strain.push_back(0.0F);
    ++(fresh_ring[k] <= region ? stats.inserted : stats.filled_at_seam);
  }
  points = std::move(out);
  strain = std::move(out_strain);
}

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
LocalResampleStats LocalResampler<D>::resample(PointSet<D>& points, std::vector<float>& strain, ThreadPool& pool) {
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
  // Widened supports: a point's Delta_i is measured from its neighbours, so
  // every point that may matter for the widest support allowed is measured,
  // on the points around it too, before the support is chosen.
  const bool widen = parameters_.widen_support;
  const double widest_allowed = kMostWidening * delta;
  const std::int64_t reach =
      widen ? support_for(widest_allowed) + rings_for(kSupportMeasureReach * h) : support_for(delta);
  if (reach >= kOutside) throw std::logic_error("local resampling: the support's rings do not fit a byte");
  // With every point flagged (a start, or a whole-surface resample) every
  // point is in R: no rings to grow.
  const bool everything = flagged_points == points.size();
  const std::optional<Rings<D>> rings =
      everything ? std::nullopt : std::optional<Rings<D>>(std::in_place, cells, flagged, reach);
  auto ring_of = [&](const Vec<D>& p) { return rings ? rings->ring(p) : std::uint8_t{0}; };
  stats.region_cells = rings ? rings->cells_within(static_cast<std::uint8_t>(region)) : flagged.size();

  // Each point's ring, and the points within reach (in the points' order).
  std::vector<std::uint8_t> ring(points.size());
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) ring[i] = ring_of(points.positions[i]);
  });
  PointSet<D> near;
  std::vector<std::uint8_t> near_ring;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (ring[i] != kOutside) {
      near.add(points.positions[i], points.normals[i]);
      near_ring.push_back(ring[i]);
    }

  AmlsSurface<D> surface(grid_, parameters_);
  if (widen && rings) {
    // Each Delta_i as the whole surface measures it: exact out to the
    // measure's reach inside `reach`. The support is grown for the widest
    // Delta_i that can reach the walked cells.
    std::vector<double> radii = widened_support_radii<D>(near.positions, delta, h, pool);
    if (radii.empty()) radii.assign(near.size(), delta);
    const std::int64_t measured = support_for(widest_allowed);
    double widest = delta;
    for (std::size_t k = 0; k < near.size(); ++k)
      if (near_ring[k] <= measured) widest = std::max(widest, radii[k]);
    const std::int64_t support = support_for(widest);
    PointSet<D> support_points;
    std::vector<double> support_radii;
    for (std::size_t k = 0; k < near.size(); ++k)
      if (near_ring[k] <= support) {
        support_points.add(near.positions[k], near.normals[k]);
        support_radii.push_back(radii[k]);
      }
    surface.set_points(std::move(support_points), std::move(support_radii));
  } else {
    surface.set_points(std::move(near));
  }
  stats.support = surface.points().size();
  surface.hash_points(pool);
  stats.normals = surface.update_normals(pool);
  stats.normals_seconds = clock.lap();

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
  splice<D>(points, strain, ring, fresh, fresh_ring, static_cast<std::uint8_t>(region),
            static_cast<std::uint8_t>(walked), options_.fill_seam, grid_, stats);
  stats.resample_seconds = clock.lap();
  return stats;
}

template class LocalResampler<2>;
template class LocalResampler<3>;

}  // namespace amls
