#include "render/point_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/geometry/point_index.hpp"
#include "core/util/thread_pool.hpp"

namespace amls {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// body(begin, end, block) over [0, n): on the pool's threads if there is one, else at once here.
std::size_t blocks_of(const ThreadPool* pool) { return pool ? static_cast<std::size_t>(pool->threads()) : 1; }
void run_blocks(ThreadPool* pool, std::size_t n, ThreadPool::Body body) {
  if (pool)
    pool->parallel_for(n, body);
  else
    body(0, n, 0);
}

// What convert() saw: how many points were undrawable, and the box of the drawable ones.
struct Converted {
  std::size_t skipped = 0;
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
};

// Converts every point into out.positions and out.normals at its own index; an
// undrawable one gets a NaN position.
template <int D>
Converted convert(const PointSet<D>& points, PreparedPoints& out, ThreadPool* pool) {
  const std::size_t n = points.size();
  out.positions.resize(n);
  out.normals.resize(n);
  std::vector<OwnCacheLine<Converted>> blocks(blocks_of(pool));
  run_blocks(pool, n, [&](std::size_t begin, std::size_t end, int block) {
    Converted& seen = blocks[static_cast<std::size_t>(block)].value;  // a block may come in pieces: add to it
    for (std::size_t i = begin; i < end; ++i) {
      const glm::vec3 p = to_vec3<D>(points.positions[i]);
      const glm::vec3 normal = to_vec3<D>(points.normals[i]);
      const float length = glm::length(normal);
      const bool drawable = finite(p) && finite(normal) && length > 0.0f && std::isfinite(length);
      out.positions[i] = drawable ? p : glm::vec3(std::numeric_limits<float>::quiet_NaN());
      out.normals[i] = drawable ? normal / length : glm::vec3(0.0f);
      if (drawable) {
        seen.lo = glm::min(seen.lo, p);
        seen.hi = glm::max(seen.hi, p);
      } else {
        ++seen.skipped;
      }
    }
  });
  Converted all;
  for (const auto& block : blocks) {
    all.skipped += block.value.skipped;
    all.lo = glm::min(all.lo, block.value.lo);
    all.hi = glm::max(all.hi, block.value.hi);
  }
  return all;
}

// bounding_sphere(positions), whose box convert() found already, with the radius found on the pool.
BoundingSphere bounds_of(const FloatPoints& positions, const Converted& box, ThreadPool* pool) {
  if (positions.empty()) return {};
  const glm::vec3 center = 0.5f * (box.lo + box.hi);
  std::vector<OwnCacheLine<float>> r2(blocks_of(pool), {0.0f});
  run_blocks(pool, positions.size(), [&](std::size_t begin, std::size_t end, int block) {
    float& r = r2[static_cast<std::size_t>(block)].value;
    for (std::size_t i = begin; i < end; ++i) r = std::max(r, glm::dot(positions[i] - center, positions[i] - center));
  });
  float largest = 0.0f;
  for (const auto& r : r2) largest = std::max(largest, r.value);
  return {center, std::sqrt(largest)};
}

// Drops the undrawable points convert() marked, noting the input index of each kept one.
void drop_undrawable(PreparedPoints& out) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.positions.size(); ++i) {
    if (std::isnan(out.positions[i].x)) continue;
    out.positions[kept] = out.positions[i];
    out.normals[kept] = out.normals[i];
    out.source_index.push_back(static_cast<std::uint32_t>(i));
    ++kept;
  }
  out.positions.resize(kept);
  out.normals.resize(kept);
}

}  // namespace

template <int D>
double estimate_spacing(const std::vector<Vec<D>>& positions) {
  const std::size_t n = positions.size();
  if (n < 2) return 0.0;
  Vec<D> lo = positions.front(), hi = positions.front();
  for (const Vec<D>& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec<D> extent = hi - lo;
  const double diagonal = extent.norm();
  if (!(diagonal > 0.0)) return 0.0;
  // The index's cell size only needs to be near the spacing: guess it as if the points
  // evenly filled a curve (2D) or surface (3D) as large as their bounding box.
  const double count = static_cast<double>(n);
  double guess = 0.0;
  if constexpr (D == 2)
    guess = extent.sum() / count;
  else
    guess = std::sqrt((extent[0] * extent[1] + extent[1] * extent[2] + extent[2] * extent[0]) / count);
  // A set thinner than assumed (a 3D curve, all points on a line) would make the guess
  // tiny and a query visit (radius / cell)^D empty cells: diagonal / sqrt(n) bounds that,
  // at worst ~sqrt(n) points per cell.
  guess = std::max(guess, diagonal / std::sqrt(count));
  PointIndex<D> index;
  index.build(positions, lo, guess);

  const std::size_t samples = std::min<std::size_t>(n, 4096);
  std::vector<double> nearest;
  nearest.reserve(samples);
  for (std::size_t s = 0; s < samples; ++s) {
    const std::size_t i = s * n / samples;
    const Vec<D>& p = positions[i];
    double best2 = std::numeric_limits<double>::infinity();
    for (double radius = guess; !std::isfinite(best2) && radius < 4.0 * diagonal; radius *= 2.0)
      index.for_each_within(p, radius, [&](std::uint32_t id, const Vec<D>& q) {
        if (id != i) best2 = std::min(best2, (q - p).squaredNorm());
      });
    if (std::isfinite(best2)) nearest.push_back(std::sqrt(best2));
  }
  if (nearest.empty()) return 0.0;
  auto middle = nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2);
  std::nth_element(nearest.begin(), middle, nearest.end());
  return *middle;
}

template <int D>
PreparedPoints prepare_points(const PointSet<D>& points, std::optional<double> spacing, ThreadPool* pool) {
  PreparedPoints out;
  prepare_points<D>(points, spacing, pool, out);
  return out;
}

template <int D>
void prepare_points(const PointSet<D>& points, std::optional<double> spacing, ThreadPool* pool, PreparedPoints& out) {
  if (points.normals.size() != points.positions.size())
    throw std::invalid_argument("point set has " + std::to_string(points.positions.size()) + " positions but " +
                                std::to_string(points.normals.size()) + " normals");
  if (points.size() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("point set too large to draw: " + std::to_string(points.size()) + " points");
  if (spacing && !(*spacing > 0.0 && std::isfinite(*spacing)))
    throw std::invalid_argument("point spacing must be a positive finite number, got " + std::to_string(*spacing));

  FloatPoints positions = std::move(out.positions), normals = std::move(out.normals);
  out = PreparedPoints{};  // of the old contents only the arrays' memory is kept
  out.positions = std::move(positions);
  out.normals = std::move(normals);
  out.dimension = D;
  out.input_count = points.size();
  const Converted converted = convert<D>(points, out, pool);
  out.skipped = converted.skipped;
  if (out.skipped > 0) drop_undrawable(out);

  if (spacing) {
    out.spacing = *spacing;
  } else if (out.skipped == 0) {
    out.spacing = estimate_spacing<D>(points.positions);
  } else {
    std::vector<Vec<D>> drawable;  // the index rejects non-finite positions
    drawable.reserve(out.source_index.size());
    for (std::uint32_t i : out.source_index) drawable.push_back(points.positions[i]);
    out.spacing = estimate_spacing<D>(drawable);
  }
  out.bounds = bounds_of(out.positions, converted, pool);
  if (!(out.spacing > 0.0)) {
    // Fewer than two distinct points: no spacing to measure; take a size that shows them.
    out.spacing = out.bounds.radius > 0.0f ? out.bounds.radius / 16.0 : 1.0;
  }
  if (!out.bounds.empty()) out.bounds.radius += static_cast<float>(out.spacing);
}

PreparedScalars prepare_scalars(std::span<const double> values, std::size_t input_count,
                                std::span<const std::uint32_t> source_index) {
  if (values.size() != input_count)
    throw std::invalid_argument("got " + std::to_string(values.size()) + " scalars for a point set of " +
                                std::to_string(input_count) + " points");
  PreparedScalars out;
  out.values.reserve(source_index.empty() ? values.size() : source_index.size());
  auto take = [&](std::size_t i) { out.values.push_back(static_cast<float>(values[i])); };
  if (source_index.empty())
    for (std::size_t i = 0; i < values.size(); ++i) take(i);
  else
    for (std::uint32_t i : source_index) take(i);
  glm::vec2 range{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()};
  for (float v : out.values)
    if (std::isfinite(v)) range = {std::min(range.x, v), std::max(range.y, v)};
  if (range.x <= range.y) out.range = range;
  return out;
}

template PreparedPoints prepare_points<2>(const PointSet<2>&, std::optional<double>, ThreadPool*);
template PreparedPoints prepare_points<3>(const PointSet<3>&, std::optional<double>, ThreadPool*);
template void prepare_points<2>(const PointSet<2>&, std::optional<double>, ThreadPool*, PreparedPoints&);
template void prepare_points<3>(const PointSet<3>&, std::optional<double>, ThreadPool*, PreparedPoints&);
template double estimate_spacing<2>(const std::vector<Vec<2>>&);
template double estimate_spacing<3>(const std::vector<Vec<3>>&);

}  // namespace amls
