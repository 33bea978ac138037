#include "core/resampler.hpp"

#include <span>
#include <stdexcept>

#include "core/root_finding.hpp"

namespace amls {

namespace {

constexpr std::uint8_t kVisited = 1;
constexpr std::uint8_t kHaveClosePoint = 2;

// Roots are located to this fraction of an edge: near machine precision for
// coordinates of order one on grids up to a few thousand cells.
constexpr double kRootTolerance = 1e-12;

bool is_positive(double value) { return value >= 0.0; }

}  // namespace

const char* to_string(Variant variant) {
  return variant == Variant::exact ? "exact" : "interpolated";
}

Variant parse_variant(const std::string& name) {
  if (name == "exact") return Variant::exact;
  if (name == "interpolated") return Variant::interpolated;
  throw std::invalid_argument("unknown variant '" + name + "' (expected exact or interpolated)");
}

template <int D>
void Resampler<D>::update_function(const AmlsSurface<D>& surface, ThreadPool& pool) {
  const Grid<D>& grid = surface.grid();
  slot_of_.clear();
  keys_.clear();
  // The walk reads the corners [I-1, I+3)^D and the far ends of their edges:
  // the box [I-1, I+3]^D less the vertices with two or more coordinates at I+3.
  for (const Vec<D>& p : surface.points().positions) {
    const IVec<D> cell = grid.cell_of(p);
    const IVec<D> lo = cell.array() - 1;
    const IVec<D> hi = cell.array() + 3;
    for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& v) {
      if ((v.array() == hi.array()).count() > 1) return;
      const std::uint64_t key = Grid<D>::key(v);
      auto [slot, inserted] = slot_of_.try_emplace(key);
      if (inserted) {
        *slot = static_cast<std::uint32_t>(keys_.size());
        keys_.push_back(key);
      }
    });
  }

  std::vector<Vec<D>> positions(keys_.size());
  for (std::size_t s = 0; s < keys_.size(); ++s) positions[s] = grid.vertex_position(Grid<D>::unkey(keys_[s]));
  values_.resize(keys_.size());
  pool.parallel_for(keys_.size(), [&](std::size_t begin, std::size_t end, int) {
    surface.evaluate_many(std::span(positions).subspan(begin, end - begin),
                          std::span(values_).subspan(begin, end - begin));
  });

  stats_ = ResampleStats{};
  stats_.vertices = keys_.size();
  for (const auto& v : values_) stats_.undefined_vertices += v.defined ? 0 : 1;
}

template <int D>
const Evaluation<D>* Resampler<D>::vertex_value(const IVec<D>& vertex) const {
  const std::uint32_t* slot = slot_of_.find(Grid<D>::key(vertex));
  return slot ? &values_[*slot] : nullptr;
}

template <int D>
void Resampler<D>::list_crossings(const AmlsSurface<D>& surface) {
  const Grid<D>& grid = surface.grid();
  flags_.assign(keys_.size(), 0);
  crossings_.clear();
  for (const Vec<D>& p : surface.points().positions) {
    const IVec<D> cell = grid.cell_of(p);
    const IVec<D> lo = cell.array() - 1;
    const IVec<D> hi = cell.array() + 2;
    for_each_index_in_box<D>(lo, hi, [&](const IVec<D>& corner) {
      const std::uint32_t from = *slot_of_.find(Grid<D>::key(corner));
      if (flags_[from] & kVisited) return;
      flags_[from] |= kVisited;
      const Evaluation<D>& f0 = values_[from];
      if (!f0.defined) return;
      for (int axis = 0; axis < D; ++axis) {
        IVec<D> end = corner;
        ++end[axis];
        const std::uint32_t to = *slot_of_.find(Grid<D>::key(end));
        const Evaluation<D>& f1 = values_[to];
        if (f1.defined && is_positive(f0.value) != is_positive(f1.value)) crossings_.push_back({from, to, axis});
      }
    });
  }
  stats_.crossings = crossings_.size();
}

template <int D>
void Resampler<D>::locate_crossings(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  const Grid<D>& grid = surface.grid();
  const double h = grid.spacing();
  std::vector<std::size_t> evaluations(static_cast<std::size_t>(pool.threads()), 0);
  std::vector<std::size_t> fallbacks(evaluations.size(), 0);

  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int block) {
    Neighbourhood<D> candidates;
    for (std::size_t c = begin; c < end; ++c) {
      Crossing& x = crossings_[c];
      const Evaluation<D>& f0 = values_[x.from];
      const Evaluation<D>& f1 = values_[x.to];
      const double linear_t = f0.value / (f0.value - f1.value);
      x.t = linear_t;
      Vec<D> normal = (1.0 - linear_t) * f0.gradient + linear_t * f1.gradient;

      if (variant == Variant::exact) {
        const Vec<D> start = grid.vertex_position(Grid<D>::unkey(keys_[x.from]));
        Vec<D> direction = Vec<D>::Zero();
        direction[x.axis] = h;
        // Every point that can reach the edge, gathered once for all iterations.
        surface.gather(start + 0.5 * direction, surface.radius() + 0.5 * h, candidates);
        const RootResult root = find_root_illinois(
            [&](double t) -> std::optional<double> {
              const Evaluation<D> e = surface.evaluate_in(candidates, start + t * direction);
              if (!e.defined) return std::nullopt;
              return e.value;
            },
            0.0, 1.0, f0.value, f1.value, kRootTolerance);
        evaluations[static_cast<std::size_t>(block)] += static_cast<std::size_t>(root.evaluations);
        if (root.ok) {
          x.t = root.t;
          const Evaluation<D> at_root = surface.evaluate_in(candidates, start + root.t * direction);
          if (at_root.defined && at_root.gradient.squaredNorm() > 0.0) normal = at_root.gradient;
        } else {
          ++fallbacks[static_cast<std::size_t>(block)];
        }
      }
      const double length = normal.norm();
      x.normal = length > 0.0 ? Vec<D>(normal / length) : Vec<D>::Unit(x.axis);
    }
  });
  for (std::size_t b = 0; b < evaluations.size(); ++b) {
    stats_.root_evaluations += evaluations[b];
    stats_.root_fallbacks += fallbacks[b];
  }
}

template <int D>
PointSet<D> Resampler<D>::resample(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  if (values_.empty() && !surface.points().empty())
    throw std::logic_error("Resampler::resample() called before update_function()");
  list_crossings(surface);
  locate_crossings(surface, variant, pool);

  const Grid<D>& grid = surface.grid();
  const double h = grid.spacing();
  PointSet<D> out;
  out.reserve(crossings_.size());
  for (const Crossing& x : crossings_) {
    // The nearer end by distance along the edge (a tie goes to the upper end, as
    // in the paper's lines 8-10).
    const std::uint32_t nearer = x.t < 0.5 ? x.from : x.to;
    if (flags_[nearer] & kHaveClosePoint) continue;
    flags_[nearer] |= kHaveClosePoint;
    Vec<D> q = grid.vertex_position(Grid<D>::unkey(keys_[x.from]));
    q[x.axis] += x.t * h;
    out.add(q, x.normal);
  }
  stats_.inserted = out.size();
  return out;
}

template class Resampler<2>;
template class Resampler<3>;

}  // namespace amls
