#include "core/resample/local_resampling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/geometry/point_index.hpp"
#include "core/util/flat_hash_map.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

// A region cell is this many h wide: a brick of the vertex field.
constexpr double kCellInH = 4.0;
// A point's ring: the Chebyshev distance, in region cells, from its cell to
// the nearest flagged cell; beyond the support's rings, kOutside.
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
  std::vector<IVec<D>> flagged;
  std::size_t flagged_points = 0;
  {
    FlatHashMap<std::uint8_t> seen;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!(strain[i] > options_.strain_limit)) continue;
      ++flagged_points;
      const IVec<D> c = cells.cell_of(points.positions[i]);
      if (seen.try_emplace(Grid<D>::key(c)).second) flagged.push_back(c);
    }
  }
  stats.flagged_cells = flagged.size();
  if (flagged.empty()) return stats;

  auto rings_for = [&](double distance) { return static_cast<std::int64_t>(std::ceil(distance / cell_size_)); };
  const std::int64_t region = rings_for(delta);  // R: the flagged cells grown by Delta
  const std::int64_t walked = region + rings_for(2.0 * h);
  const std::int64_t support = walked + rings_for(4.0 * delta + 2.0 * h);
  if (support >= kOutside) throw std::logic_error("local resampling: the support's rings do not fit a byte");
  // With every point flagged (a start, or a whole-surface resample) every
  // point is in R: no rings to grow.
  const bool everything = flagged_points == points.size();
  const std::optional<Rings<D>> rings =
      everything ? std::nullopt : std::optional<Rings<D>>(std::in_place, cells, flagged, support);
  auto ring_of = [&](const Vec<D>& p) { return rings ? rings->ring(p) : std::uint8_t{0}; };
  stats.region_cells = rings ? rings->cells_within(static_cast<std::uint8_t>(region)) : flagged.size();

  // Each point's ring, and the support's points (in the points' order).
  std::vector<std::uint8_t> ring(points.size());
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t i = begin; i < end; ++i) ring[i] = ring_of(points.positions[i]);
  });
  PointSet<D> support_points;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (ring[i] != kOutside) support_points.add(points.positions[i], points.normals[i]);
  stats.support = support_points.size();

  AmlsSurface<D> surface(grid_, parameters_);
  surface.set_points(std::move(support_points));
  surface.hash_points(pool);
  stats.normals = surface.update_normals(pool);
  stats.normals_seconds = clock.lap();

  std::vector<Vec<D>> walk;  // in the surface's (cell) order
  for (const Vec<D>& p : surface.points().positions)
    if (ring_of(p) <= walked) walk.push_back(p);
  resampler_.update_function(surface, walk, pool);
  stats.function_seconds = clock.lap();

  const PointSet<D> fresh = resampler_.resample(surface, variant_, pool);
  stats.resample = resampler_.stats();
  // The vertices the kept points near R claim: each its nearest.
  auto nearest_vertex = [&](const Vec<D>& p) {
    IVec<D> v;
    for (int a = 0; a < D; ++a) v[a] = static_cast<std::int64_t>(std::floor((p[a] - grid_.origin()[a]) / h + 0.5));
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
    if (ring[i] <= walked) {
      claimed.try_emplace(Grid<D>::key(nearest_vertex(points.positions[i])));
      seam_points.push_back(points.positions[i]);
    }
    out.add(points.positions[i], points.normals[i]);
    out_strain.push_back(strain[i]);
  }
  PointIndex<D> seam_index;
  seam_index.build(seam_points, grid_.origin(), 0.5 * h);
  auto crowds = [&](const Vec<D>& q) {
    bool near = false;
    seam_index.for_each_within(q, 0.5 * h, [&](std::uint32_t, const Vec<D>&) { near = true; });
    return near;
  };
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    const Vec<D>& q = fresh.positions[k];
    if (ring_of(q) > region) continue;
    if (claimed.find(Grid<D>::key(nearest_vertex(q))) || crowds(q)) {
      ++stats.dropped_at_seam;
      continue;
    }
    out.add(q, fresh.normals[k]);
    out_strain.push_back(0.0F);
    ++stats.inserted;
  }
  points = std::move(out);
  strain = std::move(out_strain);
  stats.resample_seconds = clock.lap();
  return stats;
}

template class LocalResampler<2>;
template class LocalResampler<3>;

}  // namespace amls
