#include "core/surface/normal_estimation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <stdexcept>

#include "core/geometry/point_index.hpp"
#include "core/math/weight.hpp"
#include "core/surface/pratt_fit.hpp"

namespace amls {

namespace {

// How many times the radius may double for a point with too few neighbours.
constexpr int kWidenings = 3;
// Neighbours per point in the orientation graph.
template <int D>
constexpr std::size_t kGraphNeighbours = D == 2 ? 4 : 10;
// Tree edges with |n_i . n_j| below this (about 72 degrees) carry the sign unreliably.
constexpr double kAmbiguousDot = 0.3;
// A part whose normals lean away from (or toward) its centroid by at least this
// much (the mean of n . (p - c) over the mean |p - c|) has a side to take: 3/4 of
// a cap's half angle in radians, so a cap from about 1.5 degrees on; a plane's
// noise stays far below it (docs/real-data.md).
constexpr double kSideLean = 0.02;

// The direction of least spread of `neighbours` about their centroid.
template <int D>
Vec<D> least_spread_direction(const std::vector<Vec<D>>& neighbours) {
  Vec<D> centroid = Vec<D>::Zero();
  for (const Vec<D>& q : neighbours) centroid += q;
  centroid /= static_cast<double>(std::max<std::size_t>(1, neighbours.size()));
  Mat<D> scatter = Mat<D>::Zero();
  for (const Vec<D>& q : neighbours) scatter += (q - centroid) * (q - centroid).transpose();
  if (neighbours.size() < 2 || !(scatter.norm() > 0.0)) return Vec<D>::Unit(D - 1);
  const Eigen::SelfAdjointEigenSolver<Mat<D>> eigen(scatter);
  return eigen.eigenvectors().col(0).normalized();
}

std::string position_text(const double* x, int d) {
  std::ostringstream text;
  text << "(";
  for (int a = 0; a < d; ++a) text << (a ? ", " : "") << x[a];
  text << ")";
  return text.str();
}

template <int D>
void check_input(const PointSet<D>& points, double radius) {
  const std::size_t n = points.size();
  if (n < static_cast<std::size_t>(D + 1))
    throw std::invalid_argument("normal estimation needs at least " + std::to_string(D + 1) + " points, got " +
                                std::to_string(n));
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw std::invalid_argument("normal estimation: the radius must be positive, got " + std::to_string(radius));
  for (std::size_t i = 0; i < n; ++i)
    if (!points.positions[i].allFinite())
      throw std::invalid_argument("point " + std::to_string(i) + " has a non-finite coordinate");
}

// Step 1's fit at each point without a carried normal: the least-spread
// direction of the neighbours within the radius seeds a Pratt fit, the radius
// doubling up to kWidenings times while too few neighbours are in reach. One
// per thread: it keeps its neighbour lists between points.
template <int D>
class PointFitter {
 public:
  PointFitter(const PointSet<D>& points, const PointIndex<D>& index, double radius)
      : points_(points), index_(index), radius_(radius) {}

  struct Result {
    Vec<D> normal = Vec<D>::Zero();  // unoriented
    bool failed = false;             // no fit: the least-spread direction of the nearest points
    bool widened = false;            // fitted beyond the radius
  };

  // Fits point i and appends its kGraphNeighbours nearest others to `graph`.
  Result fit(std::size_t i, std::vector<std::uint32_t>& graph) {
    const Vec<D>& p = points_.positions[i];
    Result result;
    bool fitted = false;
    for (int w = 0; w <= kWidenings && !fitted; ++w) {
      const double r = radius_ * static_cast<double>(1 << w);
      gather(p, r);
      if (near_.size() < static_cast<std::size_t>(D + 1)) continue;
      // The least-spread direction seeds the fit and orients it arbitrarily; the tree fixes signs.
      const Vec<D> guess = least_spread_direction<D>(positions_);
      result.normal = guess;
      PrattFit<D> pratt;
      for (const Vec<D>& q : positions_) {
        const Vec<D> u = (q - p) / r;
        pratt.add(u, weight_of_squared_ratio(u.squaredNorm()));
      }
      fitted = pratt.solve(guess, result.normal) == FitStatus::ok;
      result.widened = w > 0;
    }
    if (!fitted) {
      result.failed = true;
      if (near_.size() < static_cast<std::size_t>(D + 1)) gather_nearest(p);
      result.normal = least_spread_direction<D>(positions_);
    }
    std::sort(near_.begin(), near_.end());
    for (const auto& [d2, id] : near_) {
      if (id == i) continue;
      graph.push_back(id);
      if (graph.size() == kGraphNeighbours<D>) break;
    }
    return result;
  }

 private:
  // The points within r of p.
  void gather(const Vec<D>& p, double r) {
    near_.clear();
    positions_.clear();
    index_.for_each_within(p, r, [&](std::uint32_t id, const Vec<D>& q) {
      near_.emplace_back((q - p).squaredNorm(), id);
      positions_.push_back(q);
    });
  }

  // Nearly isolated even at the widest radius: its D + 1 nearest points,
  // however far (rare, so by brute force).
  void gather_nearest(const Vec<D>& p) {
    const std::size_t n = points_.size();
    near_.clear();
    for (std::size_t j = 0; j < n; ++j)
      near_.emplace_back((points_.positions[j] - p).squaredNorm(), static_cast<std::uint32_t>(j));
    const auto keep = std::min<std::size_t>(n, D + 2);
    std::partial_sort(near_.begin(), near_.begin() + static_cast<std::ptrdiff_t>(keep), near_.end());
    near_.resize(keep);
    positions_.clear();
    for (const auto& entry : near_) positions_.push_back(points_.positions[entry.second]);
  }

  const PointSet<D>& points_;
  const PointIndex<D>& index_;
  double radius_;
  std::vector<std::pair<double, std::uint32_t>> near_;  // (squared distance, id)
  std::vector<Vec<D>> positions_;                       // of near_, in its order
};

// The graph's edges both ways.
std::vector<std::vector<std::uint32_t>> symmetric(const std::vector<std::vector<std::uint32_t>>& graph) {
  std::vector<std::vector<std::uint32_t>> adjacent(graph.size());
  for (std::size_t i = 0; i < graph.size(); ++i)
    for (std::uint32_t j : graph[i]) {
      adjacent[i].push_back(j);
      adjacent[j].push_back(static_cast<std::uint32_t>(i));
    }
  return adjacent;
}

// How far the normals of `part` lean away from its centroid: the mean of
// n . (p - c) over the mean |p - c|; 1 on a sphere with outward normals, about
// 3/4 of the half angle on a cap, 0 on a plane.
template <int D>
double lean_from_centroid(const PointSet<D>& points, const std::vector<Vec<D>>& normals,
                          const std::vector<std::uint32_t>& part) {
  Vec<D> centroid = Vec<D>::Zero();
  for (std::uint32_t i : part) centroid += points.positions[i];
  centroid /= static_cast<double>(part.size());
  double along = 0.0, distance = 0.0;
  for (std::uint32_t i : part) {
    const Vec<D> offset = points.positions[i] - centroid;
    along += normals[i].dot(offset);
    distance += offset.norm();
  }
  return distance > 0.0 ? along / distance : 0.0;
}

// Orients `normals` along Prim's minimum spanning tree of the graph (weights
// 1 - |n_i . n_j|), from each part's highest point, whose normal points up;
// then turns a part whose normals lean toward its centroid by kSideLean or
// more (a bowl's, whose highest points are on its rim) to lean away: outward
// for a closed surface, whose n . (p - c) sums to 3 times its volume, and the
// convex side of an open one. Counts the parts and the ambiguous tree edges in `report`.
template <int D>
void orient_along_tree(const PointSet<D>& points, const std::vector<std::vector<std::uint32_t>>& adjacent,
                       std::vector<Vec<D>>& normals, NormalEstimation& report) {
  const std::size_t n = points.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double za = points.positions[a][D - 1], zb = points.positions[b][D - 1];
    return za != zb ? za > zb : a < b;
  });
  std::vector<char> done(n, 0);
  using Edge = std::tuple<double, std::uint32_t, std::uint32_t>;  // weight, to, from
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge>> frontier;
  std::vector<std::uint32_t> part;
  for (std::size_t seed : order) {
    if (done[seed]) continue;
    ++report.components;
    if (normals[seed][D - 1] < 0.0) normals[seed] = -normals[seed];
    frontier.emplace(0.0, static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed));
    part.clear();
    while (!frontier.empty()) {
      const auto [weight, j, i] = frontier.top();
      frontier.pop();
      if (done[j]) continue;
      done[j] = 1;
      part.push_back(j);
      if (j != i) {
        const double dot = normals[i].dot(normals[j]);
        if (dot < 0.0) normals[j] = -normals[j];
        if (std::abs(dot) < kAmbiguousDot && report.ambiguous_edges++ == 0) report.first_ambiguous = j;
      }
      for (std::uint32_t k : adjacent[j])
        if (!done[k]) frontier.emplace(1.0 - std::abs(normals[j].dot(normals[k])), k, j);
    }
    if (lean_from_centroid(points, normals, part) <= -kSideLean) {
      for (std::uint32_t i : part) normals[i] = -normals[i];
      ++report.turned_parts;
    }
  }
}

template <int D>
void add_warnings(const PointSet<D>& points, double widest, NormalEstimation& report) {
  if (report.components > 1)
    report.warnings.push_back("the points fall into " + std::to_string(report.components) +
                              " separate parts (no neighbours between them); each part was oriented on its own, "
                              "away from its centroid (up, for a flat part) - check parts that lie inside others");
  if (report.ambiguous_edges > 0)
    report.warnings.push_back(std::to_string(report.ambiguous_edges) +
                              " steps of the orientation tree join normals more than 72 degrees apart, so the "
                              "orientation is ambiguous there (first near point " +
                              std::to_string(report.first_ambiguous) + " at " +
                              position_text(points.positions[report.first_ambiguous].data(), D) + ")");
  if (report.failed_fits > 0)
    report.warnings.push_back(std::to_string(report.failed_fits) + " points have too few neighbours within " +
                              std::to_string(widest) +
                              " for a sphere fit; their normals are the direction of least spread of their "
                              "nearest points");
}

}  // namespace

template <int D>
NormalEstimation estimate_normals(PointSet<D>& points, double radius, ThreadPool& pool) {
  check_input(points, radius);
  const std::size_t n = points.size();
  PointIndex<D> index;
  index.build(points.positions, points.positions.front(), radius);

  NormalEstimation report;
  report.points = n;
  std::vector<Vec<D>> normals(n);
  std::vector<std::vector<std::uint32_t>> graph(n);
  std::vector<char> failed(n, 0), widened(n, 0);
  pool.parallel_for(n, [&](std::size_t begin, std::size_t end, int) {
    PointFitter<D> fitter(points, index, radius);
    for (std::size_t i = begin; i < end; ++i) {
      const typename PointFitter<D>::Result fit = fitter.fit(i, graph[i]);
      normals[i] = fit.normal;
      failed[i] = fit.failed;
      widened[i] = fit.widened;
    }
  });
  for (std::size_t i = 0; i < n; ++i) {
    report.failed_fits += static_cast<std::size_t>(failed[i]);
    report.widened += static_cast<std::size_t>(widened[i]);
  }
  orient_along_tree(points, symmetric(graph), normals, report);
  points.normals = std::move(normals);
  add_warnings(points, radius * static_cast<double>(1 << kWidenings), report);
  return report;
}

template NormalEstimation estimate_normals<2>(PointSet<2>&, double, ThreadPool&);
template NormalEstimation estimate_normals<3>(PointSet<3>&, double, ThreadPool&);

}  // namespace amls
