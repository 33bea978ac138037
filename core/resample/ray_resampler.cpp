#include "core/resample/ray_resampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/resample/segment_root.hpp"

namespace amls {

namespace {

bool is_positive(double value) { return value >= 0.0; }

// F along a ray is evaluated over the chords that reach a window of this many
// cells, selected afresh when a sample leaves it: narrower windows copy
// neighbourhoods more often, wider ones scan more far points per evaluation
// (two cells took the fewest instructions on circles and spheres, 2D and 3D).
constexpr std::int64_t kWindowCells = 2;

// floor(k / m) for m > 0 and any sign of k.
std::int64_t floor_div(std::int64_t k, std::int64_t m) { return k >= 0 ? k / m : -((-k + m - 1) / m); }

// The squared distance from p to the line through `base` along `axis`.
template <int D>
double squared_distance_to_line(const Vec<D>& base, int axis, const Vec<D>& p) {
  double d2 = 0.0;
  for (int b = 0; b < D; ++b)
    if (b != axis) d2 += (base[b] - p[b]) * (base[b] - p[b]);
  return d2;
}

// Calls fn(line) for every grid line along `axis` that passes closer than
// `radius` to p; `line` holds the line's vertex indices off the axis (0 on it).
template <int D, typename Fn>
void for_each_line_near(const Grid<D>& grid, int axis, const Vec<D>& p, double radius, Fn&& fn) {
  const double h = grid.spacing();
  IVec<D> lo = IVec<D>::Zero();
  IVec<D> hi = IVec<D>::Zero();
  for (int b = 0; b < D; ++b) {
    if (b == axis) continue;
    const double c = (p[b] - grid.origin()[b]) / h;
    lo[b] = static_cast<std::int64_t>(std::ceil(c - radius / h));
    hi[b] = static_cast<std::int64_t>(std::floor(c + radius / h));
  }
  const double r2 = radius * radius;
  for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& line) {
    if (squared_distance_to_line<D>(grid.vertex_position(line), axis, p) < r2) fn(line);
  });
}

}  // namespace

RayResampleStats& RayResampleStats::operator+=(const RayResampleStats& o) {
  rays += o.rays;
  chords += o.chords;
  intervals += o.intervals;
  samples += o.samples;
  undefined_samples += o.undefined_samples;
  crossings += o.crossings;
  root_evaluations += o.root_evaluations;
  root_fallbacks += o.root_fallbacks;
  removed += o.removed;
  inserted += o.inserted;
  return *this;
}

template <int D>
RayResampler<D>::RayResampler(const RaySettings& settings) : settings_(settings) {
  if (settings.samples_per_cell < 1)
    throw std::invalid_argument("samples per cell must be at least 1, got " + std::to_string(settings.samples_per_cell));
  if (!(settings.cluster_threshold >= 0.0) || !std::isfinite(settings.cluster_threshold))
    throw std::invalid_argument("cluster threshold must be a non-negative number of h, got " +
                                std::to_string(settings.cluster_threshold));
}

// The ray-sphere step: which lines each ball cuts, bucketed by line (a
// counting sort keyed by a sparse map, so memory follows the points).
template <int D>
void RayResampler<D>::cut_rays(const Grid<D>& grid, double radius, std::span<const Vec<D>> positions) {
  rays_.clear();
  line_points_.clear();
  const auto margin = static_cast<std::int64_t>(std::ceil(radius / grid.spacing())) + 2;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite() || !grid.contains_with_margin(positions[i], margin))
      throw std::invalid_argument("point " + std::to_string(i) + " is not finite or too far from the grid's origin");
  }
  FlatHashMap<std::uint32_t>& lines = lines_;
  std::vector<std::uint64_t>& keys = line_keys_;
  for (int axis = 0; axis < D; ++axis) {
    lines.clear();
    for (const Vec<D>& p : positions)
      for_each_line_near<D>(grid, axis, p, radius, [&](const IVec<D>& line) { ++*lines.try_emplace(Grid<D>::key(line)).first; });
    keys.clear();
    lines.for_each([&](std::uint64_t key, std::uint32_t) { keys.push_back(key); });
    std::sort(keys.begin(), keys.end());
    // Each line's count becomes the start of its run, then its fill cursor.
    auto start = static_cast<std::uint32_t>(line_points_.size());
    for (const std::uint64_t key : keys) {
      std::uint32_t& slot = *lines.find(key);
      const std::uint32_t count = slot;
      rays_.push_back({axis, Grid<D>::unkey(key), start, start + count});
      slot = start;
      start += count;
    }
    line_points_.resize(start);
    for (std::uint32_t id = 0; id < positions.size(); ++id)
      for_each_line_near<D>(grid, axis, positions[id], radius,
                            [&](const IVec<D>& line) { line_points_[(*lines.find(Grid<D>::key(line)))++] = id; });
  }
}

template <int D>
void RayResampler<D>::trace(const AmlsSurface<D>& definition, const Ray& ray, std::span<const Vec<D>> positions,
                            std::span<const Vec<D>> pseudo_normals, Scratch& scratch) const {
  const Grid<D>& grid = definition.grid();
  const double h = grid.spacing();
  const double r2 = definition.radius() * definition.radius();
  const int axis = ray.axis;
  const Vec<D> base = grid.vertex_position(ray.line);  // the line's point at the origin's coordinate on the axis
  const double axis_origin = base[axis];
  RayResampleStats& stats = scratch.stats;

  // The chords, sorted by start (ties by id, so the order is fixed).
  std::vector<Chord>& chords = scratch.chords;
  chords.clear();
  for (std::uint32_t k = ray.begin; k < ray.end; ++k) {
    const std::uint32_t id = line_points_[k];
    const Vec<D>& p = positions[id];
    const double half = std::sqrt(r2 - squared_distance_to_line<D>(base, axis, p));
    chords.push_back({p[axis] - half, p[axis] + half, id});
  }
  std::sort(chords.begin(), chords.end(),
            [](const Chord& a, const Chord& b) { return a.lo < b.lo || (a.lo == b.lo && a.id < b.id); });
  ++stats.rays;
  stats.chords += chords.size();

  const std::int64_t m = settings_.samples_per_cell;
  const double step = h / static_cast<double>(m);
  // Sample k lies at axis_origin + h (k / m): vertices where m divides k.
  auto sample_position = [&](std::int64_t k) {
    return axis_origin + h * (static_cast<double>(k) / static_cast<double>(m));
  };
  Neighbourhood<D>& neighbourhood = scratch.neighbourhood;
  auto evaluate = [&](const Vec<D>& y) { return definition.evaluate_in(neighbourhood, y); };

  for (std::size_t first = 0; first < chords.size();) {
    // One interval: the chords that overlap, transitively.
    double end = chords[first].hi;
    std::size_t last = first + 1;
    for (; last < chords.size() && chords[last].lo < end; ++last) end = std::max(end, chords[last].hi);
    const double begin = chords[first].lo;
    ++stats.intervals;

    // The samples strictly inside (begin, end).
    std::int64_t k = static_cast<std::int64_t>(std::floor((begin - axis_origin) / step));
    while (sample_position(k) <= begin) ++k;
    std::vector<std::uint32_t>& active = scratch.active;
    active.clear();
    std::size_t next_chord = first;
    std::int64_t window_cell = 0;  // the window's first cell
    bool have_window = false;
    Evaluation<D> previous;  // undefined until a sample gives a value
    double previous_y = 0.0;
    for (; sample_position(k) < end; ++k) {
      const std::int64_t sample_cell = floor_div(k, m);
      if (!have_window || sample_cell >= window_cell + kWindowCells) {
        // The chords that reach the window [first cell's start - step, last
        // cell's end]: every point within Delta of a sample in the window or of
        // the bracket ending at its first sample.
        have_window = true;
        window_cell = sample_cell;
        const double window_lo = axis_origin + h * static_cast<double>(window_cell) - step;
        const double window_hi = axis_origin + h * static_cast<double>(window_cell + kWindowCells);
        while (next_chord < last && chords[next_chord].lo < window_hi) active.push_back(static_cast<std::uint32_t>(next_chord++));
        std::erase_if(active, [&](std::uint32_t c) { return chords[c].hi <= window_lo; });
        neighbourhood.positions.clear();
        neighbourhood.normals.clear();
        for (const std::uint32_t c : active) {
          neighbourhood.positions.push_back(positions[chords[c].id]);
          neighbourhood.normals.push_back(pseudo_normals[chords[c].id]);
        }
      }
      const double y = sample_position(k);
      Vec<D> x = base;
      x[axis] = y;
      const Evaluation<D> e = evaluate(x);
      ++stats.samples;
      if (!e.defined) {
        ++stats.undefined_samples;
        previous.defined = false;
        continue;
      }
      if (previous.defined && is_positive(previous.value) != is_positive(e.value)) {
        Vec<D> start = base;
        start[axis] = previous_y;
        const Vec<D> direction = (y - previous_y) * Vec<D>::Unit(axis);
        const SegmentRoot<D> root = locate_segment_root<D>(evaluate, start, direction, previous, e,
                                                           estimate_segment_root(previous, e, direction), axis);
        ++stats.crossings;
        stats.root_evaluations += static_cast<std::size_t>(root.evaluations);
        stats.root_fallbacks += root.fallback;
        scratch.found.add(start + root.t * direction, root.normal);
      }
      previous = e;
      previous_y = y;
    }
    first = last;
  }
}

template <int D>
void RayResampler<D>::intersect(const AmlsSurface<D>& definition, std::span<const Vec<D>> positions,
                                std::span<const Vec<D>> pseudo_normals, ThreadPool& pool) {
  if (pseudo_normals.size() != positions.size())
    throw std::invalid_argument("ray resampling: " + std::to_string(positions.size()) + " points but " +
                                std::to_string(pseudo_normals.size()) + " pseudo-normals");
  stats_ = RayResampleStats{};
  cut_rays(definition.grid(), definition.radius(), positions);
  scratch_.resize(static_cast<std::size_t>(pool.threads()));
  for (Scratch& s : scratch_) {
    s.found.clear();
    s.stats = RayResampleStats{};
  }
  pool.parallel_for(rays_.size(), [&](std::size_t begin, std::size_t end, int block) {
    Scratch& scratch = scratch_[static_cast<std::size_t>(block)];
    for (std::size_t r = begin; r < end; ++r) trace(definition, rays_[r], positions, pseudo_normals, scratch);
  });
  // Blocks are contiguous runs of rays: joined in block order, the candidates
  // are in ray order whatever the thread count.
  candidates_.clear();
  for (const Scratch& s : scratch_) {
    candidates_.positions.insert(candidates_.positions.end(), s.found.positions.begin(), s.found.positions.end());
    candidates_.normals.insert(candidates_.normals.end(), s.found.normals.begin(), s.found.normals.end());
    stats_ += s.stats;
  }
}

template <int D>
PointSet<D> RayResampler<D>::remove_clusters(double h, ThreadPool& pool) {
  const std::size_t n = candidates_.size();
  const double threshold = settings_.cluster_threshold * h;
  removed_.assign(n, 0);
  if (threshold > 0.0 && n > 1) {
    candidate_tree_.build(candidates_.positions);
    scratch_.resize(static_cast<std::size_t>(pool.threads()));
    for (Scratch& s : scratch_) s.close_pairs.clear();
    pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int block) {
      Scratch& scratch = scratch_[static_cast<std::size_t>(block)];
      for (std::size_t i = begin; i < end; ++i) {
        scratch.near.clear();
        candidate_tree_.gather(candidates_.positions[i], threshold, scratch.near);
        for (const std::uint32_t j : scratch.near)
          if (j > i) scratch.close_pairs.emplace_back(static_cast<std::uint32_t>(i), j);
      }
    });
    // In candidate order (the pairs are grouped by their first candidate, in
    // order): a candidate still standing removes the later ones close to it.
    // Whether i stands is settled before its pairs, by pairs (k, i) with k < i.
    for (const Scratch& s : scratch_)
      for (const auto& [i, j] : s.close_pairs)
        if (!removed_[i]) removed_[j] = 1;
  }
  PointSet<D> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (!removed_[i]) out.add(candidates_.positions[i], candidates_.normals[i]);
  stats_.removed = n - out.size();
  stats_.inserted = out.size();
  return out;
}

template <int D>
PointSet<D> RayResampler<D>::resample(const AmlsSurface<D>& surface, ThreadPool& pool) {
  intersect(surface, surface.points().positions, surface.pseudo_normals(), pool);
  return remove_clusters(surface.grid().spacing(), pool);
}

template class RayResampler<2>;
template class RayResampler<3>;

}  // namespace amls
