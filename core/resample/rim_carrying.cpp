#include "core/resample/rim_carrying.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/grid.hpp"
#include "core/util/flat_hash_map.hpp"

namespace amls {

namespace {

// Newton steps along grad F onto F = 0. A new point's normal is the unit
// gradient there, as a crossing's is, oriented to agree with `carried`.
template <int D>
void project_on_surface(const AmlsSurface<D>& surface, Vec<D>& x, Vec<D>& normal, const Vec<D>& carried) {
  constexpr int kSteps = 4;
  const double tolerance = 1e-9 * surface.grid().spacing();
  for (int step = 0; step < kSteps; ++step) {
    const Evaluation<D> f = surface.evaluate(x);
    const double g2 = f.gradient.squaredNorm();
    if (!f.defined || !(g2 > 0.0)) return;  // keep the last position and normal
    normal = f.gradient / std::sqrt(g2);
    if (normal.dot(carried) < 0.0) normal = -normal;
    if (std::abs(f.value) <= tolerance) return;
    x -= (f.value / g2) * f.gradient;
  }
}

// The neighbour of rim sample i along the rim ahead of it (within 60 degrees
// of its rim tangent n x b): the nearest within reach, or -1. 3D only: a
// curve's rim is its ends.
std::int64_t next_along_rim(const SurfaceRim<3>& rim, std::size_t i, double reach) {
  const auto& s = rim.samples();
  const Vec<3> tangent = s.normals[i].cross(s.outward[i]);
  std::int64_t next = -1;
  double nearest = std::numeric_limits<double>::infinity();
  rim.for_each_within(s.positions[i], reach, [&](std::uint32_t k, const Vec<3>& q) {
    const Vec<3> d = q - s.positions[i];
    const double d2 = d.squaredNorm();
    if (k == i || d.dot(tangent) <= 0.5 * std::sqrt(d2) || d2 >= nearest) return;
    if (s.normals[k].dot(s.normals[i]) <= 0.0) return;  // another sheet
    nearest = d2;
    next = k;
  });
  return next;
}


// Rim points closer than a spacing to one another, or to a rim point:
// a hash of cells as wide as kRimSpacing h.
template <int D>
class RimPointHash {
 public:
  RimPointHash(const Vec<D>& origin, double h, std::size_t expected)
      : cells_(origin, kRimSpacing * h), ids_(expected) {}
  void add(const Vec<D>& p, std::uint32_t id) { ids_.try_emplace(Grid<D>::key(cells_.cell_of(p))).first->push_back(id); }
  // The distance from p to the nearest point added, if within a cell's width; else infinity.
  double nearest(const Vec<D>& p, const std::vector<Vec<D>>& positions) const {
    double nearest2 = std::numeric_limits<double>::infinity();
    const IVec<D> cell = cells_.cell_of(p);
    for_each_index_in_box<D>(IVec<D>(cell.array() - 1), IVec<D>(cell.array() + 1), [&](const IVec<D>& c) {
      if (const auto* ids = ids_.find(Grid<D>::key(c)))
        for (const std::uint32_t id : *ids) nearest2 = std::min(nearest2, (positions[id] - p).squaredNorm());
    });
    return std::sqrt(nearest2);
  }

 private:
  Grid<D> cells_;
  FlatHashMap<std::vector<std::uint32_t>> ids_;
};

}  // namespace

template <int D>
CarriedRim<D> carry_rim(const AmlsSurface<D>& surface, ThreadPool& pool) {
  const SurfaceRim<D>& rim = surface.rim();
  CarriedRim<D> out;
  if (rim.empty()) return out;
  const auto& samples = rim.samples();
  const double h = surface.grid().spacing();

  // Candidates: every rim sample, then the points that fill stretched gaps
  // ahead of each, evenly spaced on the chord between the two samples; each
  // with the outward direction and support of the sample it came from.
  typename SurfaceRim<D>::Samples candidates = samples;
  if constexpr (D == 3) {
    for (std::uint32_t i = 0; i < rim.size(); ++i) {
      const std::int64_t next = next_along_rim(rim, i, samples.radii[i] + h);
      if (next < 0) continue;
      const Vec<3> chord = samples.positions[static_cast<std::size_t>(next)] - samples.positions[i];
      const double length = chord.norm();
      if (length <= kRimGapToFill * h) continue;
      const auto pieces = static_cast<int>(std::ceil(length / h));
      for (int k = 1; k < pieces; ++k) {
        candidates.ids.push_back(i);
        candidates.positions.push_back(samples.positions[i] + (static_cast<double>(k) / pieces) * chord);
        candidates.outward.push_back(samples.outward[i]);
        candidates.normals.push_back(samples.normals[i]);
        candidates.radii.push_back(samples.radii[i]);
      }
    }
  }
  const std::size_t from_samples = samples.positions.size();
  pool.parallel_for(candidates.positions.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const Vec<D> carried = candidates.normals[k];
      project_on_surface(surface, candidates.positions[k], candidates.normals[k], carried);
    }
  });

  // Greedy thinning in the candidates' order (samples first): a candidate
  // is dropped when a kept one lies closer than kRimSpacing h.
  typename SurfaceRim<D>::Samples kept;
  RimPointHash<D> hash(surface.grid().origin(), h, candidates.positions.size());
  for (std::uint32_t k = 0; k < candidates.positions.size(); ++k) {
    const Vec<D>& p = candidates.positions[k];
    if (hash.nearest(p, kept.positions) < kRimSpacing * h) continue;
    hash.add(p, static_cast<std::uint32_t>(kept.positions.size()));
    kept.ids.push_back(candidates.ids[k]);
    kept.positions.push_back(p);
    kept.outward.push_back(candidates.outward[k]);
    kept.normals.push_back(candidates.normals[k]);
    kept.radii.push_back(candidates.radii[k]);
    ++(k < from_samples ? out.stats.carried : out.stats.inserted);
  }
  out.points.positions = kept.positions;
  out.points.normals = kept.normals;
  out.rim = SurfaceRim<D>(std::move(kept), surface.grid().origin());
  return out;
}

template <int D>
void append_rim(CarriedRim<D>& carried, double h, PointSet<D>& out) {
  if (carried.points.empty()) return;
  const std::vector<Vec<D>>& rim = carried.points.positions;
  RimPointHash<D> hash(Vec<D>::Zero(), h, rim.size());
  for (std::uint32_t k = 0; k < rim.size(); ++k) hash.add(rim[k], k);
  std::size_t left = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (hash.nearest(out.positions[k], rim) < kRimBand * h) continue;
    out.positions[left] = out.positions[k];
    out.normals[left] = out.normals[k];
    ++left;
  }
  carried.stats.crowding = out.size() - left;
  out.positions.resize(left);
  out.normals.resize(left);
  out.positions.insert(out.positions.end(), rim.begin(), rim.end());
  out.normals.insert(out.normals.end(), carried.points.normals.begin(), carried.points.normals.end());
  out.rim.assign(left, 0);
  out.rim.resize(out.size(), 1);
}

template CarriedRim<2> carry_rim<2>(const AmlsSurface<2>&, ThreadPool&);
template CarriedRim<3> carry_rim<3>(const AmlsSurface<3>&, ThreadPool&);
template void append_rim<2>(CarriedRim<2>&, double, PointSet<2>&);
template void append_rim<3>(CarriedRim<3>&, double, PointSet<3>&);

}  // namespace amls
