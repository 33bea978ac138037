#include "core/resample/resample_policy.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/point_index.hpp"

namespace amls {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Normals within 120 degrees: one sheet (SamplingQuality).
constexpr double kSameSheetCos = -0.5;
// 3D: the widest empty sector a surrounded point may have (SamplingQuality).
constexpr double kWidestSector = 150.0 * std::numbers::pi / 180.0;

// A same-sheet neighbour as seen from a point: its squared distance and its
// direction in the point's tangent space: 2D, the side of the normal line
// (side = +1 or -1); 3D, its angle in a tangent basis, in (-pi, pi].
//
// The 3D sectors are differences of sorted angles, so that more neighbours
// can only narrow them and a point surrounded within r stays surrounded
// within any larger r. A pseudo-angle such as 1 - cos, sorted, with the
// sectors tested by the sign of a cross product, is not: near the basis'
// axes it cannot tell directions less than about 1e-8 radians apart (their
// cosines round to the same number), so two neighbours in one line (at h and
// 2 h along a flat face) sorted either way, and the cross product of a pair
// sorted the wrong way round read as an empty sector of almost 360 degrees.
struct Neighbour {
  double distance2 = 0.0;
  double side = 0.0;
  double angle = 0.0;
};

// The tangent space of a point with normal n: 2D, the tangent t (rows: t);
// 3D, a basis (u, v) built from the axis least aligned with n (rows: u, v).
template <int D>
Eigen::Matrix<double, D - 1, D> tangent_basis(const Vec<D>& n) {
  Eigen::Matrix<double, D - 1, D> basis;
  if constexpr (D == 2) {
    basis << n.y(), -n.x();
  } else {
    Eigen::Index axis = 0;
    n.cwiseAbs().minCoeff(&axis);
    const Vec<3> u = n.cross(Vec<3>::Unit(axis)).normalized();
    basis.row(0) = u.transpose();
    basis.row(1) = n.cross(u).transpose();
  }
  return basis;
}

// The neighbour at offset d in the tangent space `basis`, or nothing when d is
// along the normal (it lies on no side).
template <int D>
std::optional<Neighbour> neighbour_at(const Vec<D>& d, const Eigen::Matrix<double, D - 1, D>& basis) {
  Neighbour nb;
  nb.distance2 = d.squaredNorm();
  const Eigen::Matrix<double, D - 1, 1> t = basis * d;
  if constexpr (D == 2) {
    if (t[0] == 0.0) return std::nullopt;
    nb.side = t[0] > 0.0 ? 1.0 : -1.0;
  } else {
    if (t[0] == 0.0 && t[1] == 0.0) return std::nullopt;
    nb.angle = std::atan2(t[1], t[0]);
  }
  return nb;
}

// 3D: whether the neighbours (sorted by angle) within squared distance r2
// surround the point: at least three, and no empty sector of 150 degrees,
// the one from the last round to the first included.
bool surrounded_within(std::span<const Neighbour> by_angle, double r2) {
  const Neighbour* first = nullptr;
  const Neighbour* previous = nullptr;
  int count = 0;
  for (const Neighbour& nb : by_angle) {
    if (nb.distance2 > r2) continue;
    if (previous && nb.angle - previous->angle >= kWidestSector) return false;
    if (!first) first = &nb;
    previous = &nb;
    ++count;
  }
  return count >= 3 && first->angle + 2.0 * std::numbers::pi - previous->angle < kWidestSector;
}

// 3D: sorts neighbours by their angle in the tangent plane.
void sort_by_angle(std::vector<Neighbour>& neighbours) {
  std::sort(neighbours.begin(), neighbours.end(),
            [](const Neighbour& a, const Neighbour& b) { return a.angle < b.angle; });
}

// Whether `neighbours` surround the point (SamplingQuality::gap): 2D, one on
// each side; 3D, no empty sector of 150 degrees (sorts them).
template <int D>
bool surrounded(std::vector<Neighbour>& neighbours) {
  if constexpr (D == 2) {
    bool plus = false, minus = false;
    for (const Neighbour& nb : neighbours) (nb.side > 0.0 ? plus : minus) = true;
    return plus && minus;
  } else {
    sort_by_angle(neighbours);
    return surrounded_within(neighbours, kInfinity);
  }
}

// The squared gap of one point (SamplingQuality::gap) when it exceeds
// `largest` (the largest found so far), else `largest`: in 3D, a point already
// surrounded within that distance cannot raise the maximum, and most are, so
// only the few others pay for the bisection. Sorts `neighbours`; `distances2`
// is scratch.
template <int D>
double gap2_above(std::vector<Neighbour>& neighbours, std::vector<double>& distances2, double largest) {
  if constexpr (D == 2) {
    double plus = kInfinity;
    double minus = kInfinity;
    for (const Neighbour& nb : neighbours) {
      double& side = nb.side > 0.0 ? plus : minus;
      side = std::min(side, nb.distance2);
    }
    return std::max({plus, minus, largest});
  } else {
    sort_by_angle(neighbours);
    if (surrounded_within(neighbours, largest)) return largest;
    if (!surrounded_within(neighbours, kInfinity)) return kInfinity;
    // More neighbours only narrow the empty sectors: bisect over the distances.
    distances2.clear();
    for (const Neighbour& nb : neighbours) distances2.push_back(nb.distance2);
    std::sort(distances2.begin(), distances2.end());
    std::size_t lo = 0;                      // below distances2[lo]: not surrounded
    std::size_t hi = distances2.size() - 1;  // within distances2[hi]: surrounded
    while (hi > lo) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (surrounded_within(neighbours, distances2[mid]))
        hi = mid;
      else
        lo = mid + 1;
    }
    return std::max(distances2[hi], largest);
  }
}

// Calls visit(result, neighbours, scratch, feature2) for every point, with its
// same-sheet neighbours within r (in its tangent space), a scratch vector and the smallest
// |p_i - p_j|^2 / |n_i - n_j|^2 among them (infinite when none turns), and
// `result` the Result of i's block; returns every block's Result (one per
// thread of `pool`), so that a reduction over them does not depend on how the
// points were split.
template <typename Result, int D, typename Visit>
std::vector<Result> visit_neighbourhoods(const PointSet<D>& points, double r, ThreadPool& pool, const Result& start,
                                         Visit&& visit) {
  const double r2 = r * r;
  std::vector<Result> partial(static_cast<std::size_t>(pool.threads()), start);
  PointIndex<D> index;
  index.build(points.positions, Vec<D>::Zero(), r);
  // Points in the index's cell order, so that consecutive points share their
  // candidate neighbours (every point of the 3^D cells around their cell).
  const std::vector<std::uint32_t>& order = index.order();
  pool.parallel_for(points.size(), [&](std::size_t begin, std::size_t end, int block) {
    // Accumulated in a local and stored once: the blocks' entries share a
    // cache line, and writing them per point would bounce it between cores.
    Result result = partial[static_cast<std::size_t>(block)];
    // The candidates' ids, positions and normals, side by side.
    std::vector<std::uint32_t> candidates;
    std::vector<Vec<D>> candidate_positions;
    std::vector<Vec<D>> candidate_normals;
    IVec<D> candidates_cell = IVec<D>::Zero();
    std::vector<Neighbour> neighbours;
    std::vector<double> scratch;
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t i = order[k];
      const Vec<D>& p = points.positions[i];
      const Vec<D>& normal = points.normals[i];
      const IVec<D> cell = index.cell_of(p);
      if (k == begin || cell != candidates_cell) {
        candidates.clear();
        candidate_positions.clear();
        candidate_normals.clear();
        index.for_each_in_cells(cell.array() - 1, cell.array() + 1, [&](std::uint32_t id, const Vec<D>& q) {
          candidates.push_back(id);
          candidate_positions.push_back(q);
          candidate_normals.push_back(points.normals[id]);
        });
        candidates_cell = cell;
      }
      const Eigen::Matrix<double, D - 1, D> basis = tangent_basis<D>(normal);
      neighbours.clear();
      double feature2 = kInfinity;
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const Vec<D> d = candidate_positions[c] - p;
        const double d2 = d.squaredNorm();
        const Vec<D>& other = candidate_normals[c];
        if (d2 > r2 || candidates[c] == i || other.dot(normal) <= kSameSheetCos) continue;
        const double turn2 = (other - normal).squaredNorm();
        if (turn2 > 0.0) feature2 = std::min(feature2, d2 / turn2);
        if (const std::optional<Neighbour> nb = neighbour_at<D>(d, basis)) neighbours.push_back(*nb);
      }
      visit(result, neighbours, scratch, feature2);
    }
    partial[static_cast<std::size_t>(block)] = result;
  });
  return partial;
}

struct PartialQuality {
  double gap2 = 0.0;
  double feature2 = kInfinity;
};

}  // namespace

template <int D>
SamplingQuality sampling_quality(const PointSet<D>& points, double h, double radius, ThreadPool& pool) {
  SamplingQuality quality{0.0, kInfinity};
  if (points.size() < 2) return quality;
  const std::vector<PartialQuality> partial = visit_neighbourhoods<PartialQuality>(
      points, radius * h, pool, PartialQuality{},
      [](PartialQuality& result, std::vector<Neighbour>& neighbours, std::vector<double>& scratch, double feature2) {
        result.feature2 = std::min(result.feature2, feature2);
        result.gap2 = gap2_above<D>(neighbours, scratch, result.gap2);
      });
  for (const PartialQuality& p : partial) {
    quality.gap = std::max(quality.gap, p.gap2);
    quality.feature_size = std::min(quality.feature_size, p.feature2);
  }
  quality.gap = std::sqrt(quality.gap) / h;
  quality.feature_size = std::sqrt(quality.feature_size) / h;
  return quality;
}

template <int D>
std::size_t unsurrounded_points(const PointSet<D>& points, double h, double radius, ThreadPool& pool) {
  if (points.size() < 2) return points.size();
  const std::vector<std::size_t> partial = visit_neighbourhoods<std::size_t>(
      points, radius * h, pool, std::size_t{0},
      [](std::size_t& count, std::vector<Neighbour>& neighbours, std::vector<double>&, double) {
        count += surrounded<D>(neighbours) ? 0 : 1;
      });
  std::size_t count = 0;
  for (const std::size_t c : partial) count += c;
  return count;
}

ResamplePolicy ResamplePolicy::parse(const std::string& text) {
  ResamplePolicy p;
  if (text == "always") return p;
  if (text == "auto") {
    p.kind = Kind::automatic;
    return p;
  }
  if (text == "local") {
    p.kind = Kind::local;
    return p;
  }
  const std::string prefix = "every:";
  if (text.rfind(prefix, 0) == 0) {
    std::size_t used = 0;
    int k = 0;
    try {
      k = std::stoi(text.substr(prefix.size()), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == text.size() - prefix.size() && k >= 1) {
      p.kind = Kind::every;
      p.every = k;
      return p;
    }
  }
  throw std::invalid_argument("--resample must be always, auto, local or every:K with K >= 1, got '" + text + "'");
}

std::string ResamplePolicy::to_string() const {
  switch (kind) {
    case Kind::always: return "always";
    case Kind::automatic: return "auto";
    case Kind::every: return "every:" + std::to_string(every);
    case Kind::local: return "local";
  }
  return "always";
}

double ResamplePolicy::search_radius() const { return std::max(max_gap, std::sqrt(3.0) * min_feature_size); }

template <int D>
bool ResamplePolicy::resample_now(std::size_t step, const PointSet<D>& points, double h, ThreadPool& pool) const {
  switch (kind) {
    case Kind::always:
    case Kind::local: return true;
    case Kind::every: return step % static_cast<std::size_t>(every) == 0;
    case Kind::automatic: {
      if (step == 0 || points.size() < 2) return true;
      const SamplingQuality q = sampling_quality(points, h, search_radius(), pool);
      return q.gap > max_gap || q.feature_size < min_feature_size;
    }
  }
  return true;
}

template SamplingQuality sampling_quality<2>(const PointSet<2>&, double, double, ThreadPool&);
template SamplingQuality sampling_quality<3>(const PointSet<3>&, double, double, ThreadPool&);
template std::size_t unsurrounded_points<2>(const PointSet<2>&, double, double, ThreadPool&);
template std::size_t unsurrounded_points<3>(const PointSet<3>&, double, double, ThreadPool&);
template bool ResamplePolicy::resample_now<2>(std::size_t, const PointSet<2>&, double, ThreadPool&) const;
template bool ResamplePolicy::resample_now<3>(std::size_t, const PointSet<3>&, double, ThreadPool&) const;

}  // namespace amls
