#include "core/resample/resampler.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>

#include "core/resample/segment_root.hpp"
#include "core/resample/sheet_edge.hpp"
#include "core/surface/local_support.hpp"
#include "core/util/block_join.hpp"
#include "core/util/parallel_compact.hpp"

namespace amls {

namespace {

// Bit masks over a brick's vertices (VertexField::local_index order) for the
// edges along each axis: inner[axis] marks the vertices whose edge ends in the
// same brick (coordinate < 3 along the axis), first_layer[axis] those with
// coordinate 0, where the edges from the brick below end; stride[axis] is the
// step in local index along the axis.
template <int D>
struct BrickEdgeMasks {
  std::array<std::uint64_t, D> inner{};
  std::array<std::uint64_t, D> first_layer{};
  std::array<std::uint32_t, D> stride{};
  constexpr BrickEdgeMasks() {
    for (int axis = 0; axis < D; ++axis) stride[axis] = std::uint32_t{1} << (VertexField<D>::kBrickShift * axis);
    for (std::uint32_t l = 0; l < VertexField<D>::kBrickVolume; ++l)
      for (int axis = 0; axis < D; ++axis) {
        const std::uint32_t coordinate = (l >> (VertexField<D>::kBrickShift * axis)) % VertexField<D>::kBrickSide;
        if (coordinate + 1 < VertexField<D>::kBrickSide) inner[axis] |= std::uint64_t{1} << l;
        if (coordinate == 0) first_layer[axis] |= std::uint64_t{1} << l;
      }
  }
};

// A crossing's position along its edge (from f0 to f1, length h, along
// `axis`) before any further evaluation of F: the linear interpolant's zero,
// which is the interpolated variant's point, or the root finder's first
// guess for the exact one.
template <int D>
double estimated_crossing(const Evaluation<D>& f0, const Evaluation<D>& f1, int axis, double h, Variant variant) {
  if (variant == Variant::interpolated) return linear_segment_root(f0, f1);
  return estimate_segment_root<D>(f0, f1, Vec<D>(h * Vec<D>::Unit(axis)));
}

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
std::vector<Vec<D>> Resampler<D>::walk_positions(const AmlsSurface<D>& surface, ThreadPool& pool) {
  std::vector<Vec<D>> out = surface.points().positions;
  // Widened supports carry the surface across gaps wider than a walk's
  // block: walks over each sparse point's tangent disc reach its vertices.
  if (surface.widened())
    append_widened_walk_positions<D>(surface.points().positions, surface.pseudo_normals(), surface.support_radii(),
                                     surface.radius(), surface.grid().spacing(), out, pool);
  return out;
}

template <int D>
void Resampler<D>::update_function(const AmlsSurface<D>& surface, ThreadPool& pool) {
  if (!surface.widened()) {
    update_function(surface, surface.points().positions, pool);  // no copy of the points
    return;
  }
  update_function(surface, walk_positions(surface, pool), pool);
}

template <int D>
void Resampler<D>::update_function(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& walk_positions,
                                   ThreadPool& pool) {
  const Grid<D>& grid = surface.grid();
  field_.clear();
  stats_ = ResampleStats{};
  walk_.mark(grid, walk_positions, field_, pool);
  const std::vector<Mask>& needed = walk_.needed();
  for (const Mask m : needed) stats_.vertices += static_cast<std::size_t>(std::popcount(m));
  signs_.assign(needed.size(), BrickSigns{});

  // The needed vertices' values only, brick after brick: about a third of
  // the slots on a surface, and no pass over the whole slot range.
  value_first_.resize(needed.size());
  std::size_t needed_so_far = 0;
  for (std::size_t b = 0; b < needed.size(); ++b) {
    value_first_[b] = needed_so_far;
    needed_so_far += static_cast<std::size_t>(std::popcount(needed[b]));
  }
  values_.resize(needed_so_far);

  // One gather per brick serves its vertices here and, in locate_crossings(),
  // the root finding on every edge that starts in it: it holds every point
  // within Delta (with widened supports: whose Delta_i reaches) of the
  // brick's box of edges, [origin, origin + 4h]^D.
  const double h = grid.spacing();
  const double box_side = h * static_cast<double>(VertexField<D>::kBrickSide);
  const double cube_reach = surface.radius() + 0.5 * h * std::sqrt(static_cast<double>(D));
  const std::size_t bricks = field_.slots() / VertexField<D>::kBrickVolume;
  brick_points_.reset(bricks, pool.threads());
  pool.parallel_for(bricks, [&](std::size_t begin, std::size_t end, int block) {
    Neighbourhood<D> neighbourhood;
    std::array<Vec<D>, AmlsSurface<D>::kCubeCorners> corners;
    std::array<Evaluation<D>, AmlsSurface<D>::kCubeCorners> corner_values;
    for (std::size_t b = begin; b < end; ++b) {
      const auto first = static_cast<std::uint32_t>(b * VertexField<D>::kBrickVolume);
      const Vec<D> box_lo = grid.vertex_position(field_.vertex_of(first));
      const Vec<D> box_hi = box_lo.array() + box_side;
      surface.gather_ids(box_lo, box_hi, surface.radius(), brick_points_.start(b, block));
      brick_points_.finish(b, block);
      // Vertices are evaluated by cubes of 2^D, each from the brick's points
      // within reach of that cube, so that few candidates are wasted.
      const std::span<const std::uint32_t> brick_ids = brick_points_.of(b);
      const IVec<D> brick_origin = field_.vertex_of(first);
      const std::uint64_t brick_needed = needed[b];
      BrickSigns& signs = signs_[b];
      for_each_index_in_box<D>(IVec<D>::Zero(), IVec<D>::Ones(), [&](const IVec<D>& cube) {
        const IVec<D> lo = 2 * cube;
        std::array<std::uint32_t, AmlsSurface<D>::kCubeCorners> locals;
        int cube_needed = 0;
        for (int v = 0; v < AmlsSurface<D>::kCubeCorners; ++v) {
          const IVec<D> offset = lo + corner_offset<D>(v);
          locals[v] = VertexField<D>::slot_in_brick(0, offset);
          corners[v] = grid.vertex_position(brick_origin + offset);
          cube_needed += static_cast<int>((brick_needed >> locals[v]) & 1);
        }
        if (cube_needed == 0) return;
        const Vec<D> cube_centre = grid.vertex_position(brick_origin + lo).array() + 0.5 * h;
        surface.select(brick_ids, cube_centre, cube_reach, neighbourhood);
        // One pass for all corners pays when most of them are needed.
        const bool whole_cube = 2 * cube_needed >= AmlsSurface<D>::kCubeCorners;
        if (whole_cube) surface.evaluate_cube(neighbourhood, corners, corner_values);
        for (int v = 0; v < AmlsSurface<D>::kCubeCorners; ++v) {
          if (!((brick_needed >> locals[v]) & 1)) continue;
          const Evaluation<D>& value = value_at(first + locals[v]) =
              whole_cube ? corner_values[v] : surface.evaluate_in(neighbourhood, corners[v]);
          const auto bit = static_cast<Mask>(Mask{1} << locals[v]);
          if (value.defined) signs.defined |= bit;
          if (value.defined && value.value >= 0.0) signs.positive |= bit;
        }
      });
    }
  });
  for (std::size_t b = 0; b < signs_.size(); ++b)
    stats_.undefined_vertices += static_cast<std::size_t>(std::popcount(static_cast<Mask>(needed[b] & ~signs_[b].defined)));
  function_updated_ = true;
}

template <int D>
const Evaluation<D>* Resampler<D>::vertex_value(const IVec<D>& vertex) const {
  const std::optional<std::uint32_t> slot = field_.find(vertex);
  if (!slot) return nullptr;
  const bool needed = (walk_.needed()[*slot / VertexField<D>::kBrickVolume] >> (*slot % VertexField<D>::kBrickVolume)) & 1;
  return needed ? &value_at(*slot) : nullptr;
}

template <int D>
void Resampler<D>::list_crossings(Variant variant, double h, ThreadPool& pool) {
  static constexpr BrickEdgeMasks<D> kEdges;
  constexpr std::int64_t side = VertexField<D>::kBrickSide;
  constexpr std::uint32_t volume = VertexField<D>::kBrickVolume;
  constexpr auto last = static_cast<std::uint32_t>(side - 1);  // the last layer's coordinate
  std::vector<OwnCacheLine<std::vector<Crossing>>> found(static_cast<std::size_t>(pool.threads()));
  pool.parallel_for(signs_.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::vector<Crossing>& out = found[static_cast<std::size_t>(block)].value;
    for (std::size_t b = begin; b < end; ++b) {
      const auto first = static_cast<std::uint32_t>(b * volume);
      const IVec<D> origin = field_.vertex_of(first);
      const std::uint64_t defined = signs_[b].defined;
      const std::uint64_t positive = signs_[b].positive;
      // Per axis, the vertices whose edge along it has a defined sign change:
      // edge masks, so that each brick is a few word operations.
      std::array<std::uint64_t, D> crossing;
      std::array<std::uint32_t, D> upper_first{};  // the brick across the upper face, where the last layer's edges end
      std::uint64_t any = 0;
      for (int axis = 0; axis < D; ++axis) {
        const std::uint32_t stride = kEdges.stride[axis];
        crossing[axis] = defined & (defined >> stride) & (positive ^ (positive >> stride)) & kEdges.inner[axis];
        if (const std::optional<std::uint32_t> upper = field_.find(origin + side * IVec<D>::Unit(axis))) {
          const BrickSigns& next = signs_[*upper / volume];
          const std::uint32_t last_layer = last * stride;
          const std::uint64_t next_defined = (next.defined & kEdges.first_layer[axis]) << last_layer;
          const std::uint64_t next_positive = (next.positive & kEdges.first_layer[axis]) << last_layer;
          crossing[axis] |= defined & next_defined & (positive ^ next_positive);
          upper_first[axis] = *upper;
        }
        any |= crossing[axis];
      }
      // In slot order, then axis order: the order of a walk over the brick's vertices.
      for (; any != 0; any &= any - 1) {
        const auto l = static_cast<std::uint32_t>(std::countr_zero(any));
        for (int axis = 0; axis < D; ++axis) {
          if (!((crossing[axis] >> l) & 1)) continue;
          const std::uint32_t stride = kEdges.stride[axis];
          const std::uint32_t from = first + l;
          const std::uint32_t to =
              (kEdges.inner[axis] >> l) & 1 ? from + stride : upper_first[axis] + l - last * stride;
          out.push_back({from, to, axis, estimated_crossing(value_at(from), value_at(to), axis, h, variant), Vec<D>::Zero()});
        }
      }
    }
  });
  join_blocks(found, crossings_, pool);
  stats_.crossings = crossings_.size();
}

template <int D>
void Resampler<D>::drop_beyond_rim(const CarriedRim<D>& rim, const AmlsSurface<D>& surface, ThreadPool& pool) {
  const Grid<D>& grid = surface.grid();
  const double h = grid.spacing();
  std::vector<std::uint8_t> inside(crossings_.size());
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t c = begin; c < end; ++c) {
      const Crossing& x = crossings_[c];
      Vec<D> q = grid.vertex_position(field_.vertex_of(x.from));
      q[x.axis] += x.t * h;
      const auto near_old_point = [&] { return surface.has_point_within(q, kRimHold * h); };
      inside[c] = inside_rim(rim, h, q, Vec<D>(value_at(x.from).gradient + value_at(x.to).gradient), near_old_point);
    }
  });
  const std::size_t listed = crossings_.size();
  keep_in_order(crossings_, crossings_scratch_, [&](const Crossing&, std::size_t c) { return inside[c] != 0; }, pool);
  stats_.beyond_rim = listed - crossings_.size();
}

template <int D>
void Resampler<D>::locate_crossings(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  const Grid<D>& grid = surface.grid();
  const double h = grid.spacing();
  std::vector<std::size_t> evaluations(static_cast<std::size_t>(pool.threads()), 0);
  std::vector<std::size_t> fallbacks(evaluations.size(), 0);
  std::vector<std::size_t> jumps(evaluations.size(), 0);
  std::vector<std::size_t> past_edges(evaluations.size(), 0);

  // Each crossing's root finding reads every point within Delta of its edge,
  // i.e. within Delta + h/2 of the edge's midpoint (with widened supports:
  // Delta_i). Crossings are listed brick
  // by brick, and a brick's crossings lie close together, so a selection made
  // with kReuseMargin to spare serves the following crossings of the brick
  // whose midpoints are within that margin of its centre. The extra points'
  // supports reach no y on the edge: evaluate_in() weights them by
  // exactly 0, so F's bits are those of a selection per crossing (and the
  // orientation filter keeps the same points: see Neighbourhood::consistent).
  const double reuse_margin = kReuseMargin * h;
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int block) {
    // Counted locally and added once: the blocks' counters share a cache line.
    std::size_t block_evaluations = 0;
    std::size_t block_fallbacks = 0;
    std::size_t block_jumps = 0;
    std::size_t block_past_edges = 0;
    Neighbourhood<D> candidates;
    std::size_t candidates_brick = std::numeric_limits<std::size_t>::max();
    Vec<D> candidates_centre = Vec<D>::Zero();
    for (std::size_t c = begin; c < end; ++c) {
      Crossing& x = crossings_[c];
      const Evaluation<D>& f0 = value_at(x.from);
      const Evaluation<D>& f1 = value_at(x.to);
      SegmentRoot<D> root;
      bool past_edge = false;
      if (variant == Variant::exact) {
        const Vec<D> start = grid.vertex_position(field_.vertex_of(x.from));
        Vec<D> direction = Vec<D>::Zero();
        direction[x.axis] = h;
        // Every point that can reach the edge, taken once for all iterations
        // from the points gathered for the edge's brick.
        const std::size_t brick = x.from / VertexField<D>::kBrickVolume;
        const Vec<D> midpoint = start + 0.5 * direction;
        if (brick != candidates_brick || (midpoint - candidates_centre).squaredNorm() > reuse_margin * reuse_margin) {
          surface.select(brick_points_.of(brick), midpoint, surface.radius() + 0.5 * h + reuse_margin, candidates);
          candidates_brick = brick;
          candidates_centre = midpoint;
        }
        root = locate_segment_root<D>([&](const Vec<D>& y) { return surface.evaluate_in(candidates, y); }, start,
                                      direction, f0, f1, x.t, x.axis);
        block_evaluations += static_cast<std::size_t>(root.evaluations);
        block_fallbacks += root.fallback ? 1 : 0;
        block_jumps += root.jump ? 1 : 0;
        // Only where both sides of a sheet are within reach (the
        // neighbourhood's normals disagree) can the sheet end unseen by the
        // rim test: elsewhere the test costs nothing.
        past_edge = !root.jump && surface.parameters().orientation_filter && !candidates.consistent &&
                    beyond_sheet_edge<D>(candidates, Vec<D>(start + root.t * direction), root.normal, h,
                                                      surface.radius());
        block_past_edges += past_edge ? 1 : 0;
      } else {
        root = interpolate_segment_root(f0, f1, x.axis);
      }
      // A crossing that makes no point is marked by a t off the edge, for the cut below.
      x.t = root.jump || past_edge ? kNoPointMark : root.t;
      x.normal = root.normal;
    }
    evaluations[static_cast<std::size_t>(block)] += block_evaluations;
    fallbacks[static_cast<std::size_t>(block)] += block_fallbacks;
    jumps[static_cast<std::size_t>(block)] += block_jumps;
    past_edges[static_cast<std::size_t>(block)] += block_past_edges;
  });
  for (std::size_t b = 0; b < evaluations.size(); ++b) {
    stats_.root_evaluations += evaluations[b];
    stats_.root_fallbacks += fallbacks[b];
    stats_.jumps += jumps[b];
    stats_.past_sheet_edge += past_edges[b];
  }
  if (stats_.jumps + stats_.past_sheet_edge > 0)
    keep_in_order(crossings_, crossings_scratch_, [](const Crossing& x, std::size_t) { return x.t != kNoPointMark; },
                  pool);
}

template <int D>
std::vector<double>& Resampler<D>::slot_distances() {
  // All kFar between uses (each use resets the entries it set), so that a use
  // touches only its crossings' vertices, not every slot.
  slot_distances_.resize(std::max(slot_distances_.size(), field_.slots()), kFar);
  return slot_distances_;
}

template <int D>
void Resampler<D>::drop_certain_losers(double uncertainty, ThreadPool& pool) {
  // A crossing at estimated t lies within `uncertainty` of t (assumed), so its
  // distance to an edge end is known to that much, and so is which end is
  // nearer unless t is that close to the middle. At each vertex, the smallest
  // distance any crossing certainly assigned to it can have is an upper bound
  // on the winner's; a crossing whose every possible distance to every
  // possible nearer end exceeds that bound loses wherever it lands, and the
  // crossing it loses to is kept here. So, where the estimates are that good,
  // keep_closest_crossings() on the crossings left chooses as it would on all
  // of them.
  const double eps = uncertainty;
  std::vector<double>& best_bound = slot_distances();
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t c = begin; c < end; ++c) {
      const Crossing& x = crossings_[c];
      const bool upper_half = x.t >= 0.5;
      const bool certain = upper_half ? x.t - eps >= 0.5 : x.t + eps < 0.5;
      if (certain) lower_to(best_bound[upper_half ? x.to : x.from], (upper_half ? 1.0 - x.t : x.t) + eps);
    }
  });
  keep_in_order(
      crossings_, crossings_scratch_,
      [&](const Crossing& x, std::size_t) {
        const bool at_from = (x.t - eps < 0.5) & (x.t - eps <= best_bound[x.from]);
        const bool at_to = (x.t + eps >= 0.5) & (1.0 - x.t - eps <= best_bound[x.to]);
        return at_from | at_to;
      },
      pool);
  // Each bound set above is that of a crossing kept (it may win where its own
  // bound is), so resetting the kept crossings' ends resets them all.
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t c = begin; c < end; ++c) {
      store_shared(best_bound[crossings_[c].from], kFar);
      store_shared(best_bound[crossings_[c].to], kFar);
    }
  });
  stats_.located = crossings_.size();
}

template <int D>
void Resampler<D>::keep_closest_crossings(ThreadPool& pool) {
  // HAVECLOSEPOINT lets one crossing per vertex through: of the crossings
  // whose nearer edge end is that vertex, the paper keeps the first in walk
  // order; we keep the one nearest to the vertex (ties: the first listed). The
  // curve passes closest to the vertex there, so the kept point sits mid-way
  // between its neighbours instead of at one end of a gap (the effect on
  // spacings and errors: docs/design.md). The nearest distance per vertex is
  // found first, then the first crossing listed at it, each as a minimum that
  // any thread order reaches alike.
  std::vector<double>& closest_distance = slot_distances();
  closest_crossing_.resize(closest_distance.size());
  auto nearer_end = [](const Crossing& x) { return x.t < 0.5 ? x.from : x.to; };
  auto distance = [](const Crossing& x) { return std::min(x.t, 1.0 - x.t); };
  const std::size_t n = crossings_.size();
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t slot = nearer_end(crossings_[k]);
      lower_to(closest_distance[slot], distance(crossings_[k]));
      store_shared(closest_crossing_[slot], std::numeric_limits<std::uint32_t>::max());
    }
  });
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t slot = nearer_end(crossings_[k]);
      if (distance(crossings_[k]) == closest_distance[slot])
        lower_to(closest_crossing_[slot], static_cast<std::uint32_t>(k));
    }
  });
  keep_in_order(
      crossings_, crossings_scratch_, [&](const Crossing& x, std::size_t k) { return closest_crossing_[nearer_end(x)] == k; }, pool);
  // Every vertex offered a distance above has exactly one crossing kept.
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) closest_distance[nearer_end(crossings_[k])] = kFar;
  });
}

template <int D>
PointSet<D> Resampler<D>::resample(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  if (!function_updated_) throw std::logic_error("Resampler::resample() called before update_function()");
  function_updated_ = false;
  const Grid<D>& grid = surface.grid();
  const double h = grid.spacing();
  list_crossings(variant, h, pool);
  CarriedRim<D> rim = carry_rim(surface, pool);
  if (!rim.rim.empty()) drop_beyond_rim(rim, surface, pool);
  // Only crossings that may win HAVECLOSEPOINT are located: a third fewer
  // root findings in 2D. The interpolated variant's estimates are its points.
  drop_certain_losers(variant == Variant::exact ? kEstimateUncertainty : 0.0, pool);
  locate_crossings(surface, variant, pool);
  keep_closest_crossings(pool);

  PointSet<D> out;
  out.positions.resize(crossings_.size());
  out.normals.resize(crossings_.size());
  pool.parallel_for(crossings_.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      const Crossing& x = crossings_[k];
      out.positions[k] = grid.vertex_position(field_.vertex_of(x.from));
      out.positions[k][x.axis] += x.t * h;
      out.normals[k] = x.normal;
    }
  });
  append_rim(rim, h, out);
  stats_.rim_samples = surface.rim().size();
  stats_.beyond_rim += rim.stats.crowding;
  stats_.rim_carried = rim.stats.carried;
  stats_.rim_inserted = rim.stats.inserted;
  stats_.inserted = out.size();
  return out;
}

template class Resampler<2>;
template class Resampler<3>;

}  // namespace amls
