#include "core/surface/surface_rim.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/geometry/grid.hpp"
#include "core/math/weight.hpp"

namespace amls {

namespace {

// A unit vector orthogonal to the unit vector n.
Vec<3> any_orthogonal(const Vec<3>& n) {
  const Vec<3> axis = std::abs(n.x()) < 0.9 ? Vec<3>::UnitX() : Vec<3>::UnitY();
  return n.cross(axis).normalized();
}

// The kRimNeighbours nearest of the neighbours' offsets.
template <int D>
std::span<const Vec<D>> nearest_offsets(std::span<const RimNeighbour<D>> neighbours) {
  thread_local std::vector<Vec<D>> offsets;
  offsets.clear();
  for (const RimNeighbour<D>& n : neighbours) offsets.push_back(n.offset);
  const std::size_t count = std::min<std::size_t>(kRimNeighbours, offsets.size());
  std::partial_sort(offsets.begin(), offsets.begin() + static_cast<std::ptrdiff_t>(count), offsets.end(),
                    [](const Vec<D>& a, const Vec<D>& b) { return a.squaredNorm() < b.squaredNorm(); });
  return std::span<const Vec<D>>(offsets).first(count);
}

// Whether some neighbour lies across the gap that `outward` points into:
// within 60 degrees of it, and within its bridge of the point (tangentially).
template <int D>
bool bridged(const Vec<D>& normal, const Vec<D>& outward, std::span<const RimNeighbour<D>> neighbours) {
  return std::any_of(neighbours.begin(), neighbours.end(), [&](const RimNeighbour<D>& n) {
    const Vec<D> tangential = n.offset - normal * normal.dot(n.offset);
    const double length2 = tangential.squaredNorm();
    const double along = tangential.dot(outward);
    return length2 <= n.bridge * n.bridge && along > 0.0 && along * along > 0.25 * length2;
  });
}

// The outward direction of the widest gap among the nearest offsets, if wider than kRimGap.
std::optional<Vec<2>> widest_gap(const Vec<2>& normal, std::span<const Vec<2>> offsets) {
  // A curve's end: every neighbour on one side along the tangent.
  const Vec<2> tangent(-normal.y(), normal.x());
  int ahead = 0;
  int behind = 0;
  for (const Vec<2>& o : offsets) {
    const double along = o.dot(tangent);
    ahead += along > 0.0 ? 1 : 0;
    behind += along < 0.0 ? 1 : 0;
  }
  if (ahead + behind == 0 || (ahead > 0 && behind > 0)) return std::nullopt;
  return ahead > 0 ? Vec<2>(-tangent) : tangent;
}

std::optional<Vec<3>> widest_gap(const Vec<3>& normal, std::span<const Vec<3>> offsets) {
  const Vec<3> e1 = any_orthogonal(normal);
  const Vec<3> e2 = normal.cross(e1);
  thread_local std::vector<double> angles;
  angles.clear();
  for (const Vec<3>& o : offsets) {
    const double x = o.dot(e1);
    const double y = o.dot(e2);
    if (x == 0.0 && y == 0.0) continue;  // straight above or below: no direction
    angles.push_back(std::atan2(y, x));
  }
  if (angles.size() < 2) return std::nullopt;
  std::sort(angles.begin(), angles.end());
  // The widest gap between consecutive directions, the wrap-around included.
  double widest = angles.front() + 2.0 * std::numbers::pi - angles.back();
  double start = angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k)
    if (angles[k] - angles[k - 1] > widest) {
      widest = angles[k] - angles[k - 1];
      start = angles[k - 1];
    }
  if (widest <= kRimGap) return std::nullopt;
  const double bisector = start + 0.5 * widest;
  return Vec<3>(std::cos(bisector) * e1 + std::sin(bisector) * e2);
}

}  // namespace

template <int D>
std::optional<Vec<D>> rim_outward(const Vec<D>& normal, std::span<const RimNeighbour<D>> neighbours, bool carried) {
  const std::optional<Vec<D>> outward = widest_gap(normal, nearest_offsets<D>(neighbours));
  if (outward && !carried && bridged<D>(normal, *outward, neighbours)) return std::nullopt;
  return outward;
}

template std::optional<Vec<2>> rim_outward<2>(const Vec<2>&, std::span<const RimNeighbour<2>>, bool);
template std::optional<Vec<3>> rim_outward<3>(const Vec<3>&, std::span<const RimNeighbour<3>>, bool);

template <int D>
SurfaceRim<D>::SurfaceRim(Samples samples, const Vec<D>& origin) : samples_(std::move(samples)) {
  if (empty()) return;
  const double widest = *std::max_element(samples_.radii.begin(), samples_.radii.end());
  index_.build(samples_.positions, origin, widest);
  reached_cells_.reserve(samples_.positions.size() * 9);
  for (const Vec<D>& p : samples_.positions) {
    const IVec<D> cell = index_.cell_of(p);
    for_each_index_in_box<D>(IVec<D>(cell.array() - 1), IVec<D>(cell.array() + 1),
                             [&](const IVec<D>& c) { reached_cells_.try_emplace(Grid<D>::key(c)); });
  }
}

template <int D>
bool SurfaceRim<D>::near(const Vec<D>& x) const {
  return !empty() && reached_cells_.find(Grid<D>::key(index_.cell_of(x))) != nullptr;
}

template <int D>
std::optional<double> SurfaceRim<D>::side(const Vec<D>& x, const Vec<D>& normal) const {
  if (!near(x)) return std::nullopt;
  double sum_w = 0.0;
  double sum = 0.0;
  const IVec<D> cell = index_.cell_of(x);
  index_.for_each_in_cells(IVec<D>(cell.array() - 1), IVec<D>(cell.array() + 1),
                           [&](std::uint32_t k, const Vec<D>& p) {
                             if (samples_.normals[k].dot(normal) < kRimFacing) return;  // another sheet
                             const Vec<D> d = x - p;
                             const double r = samples_.radii[k];
                             const double w = weight_of_squared_ratio(d.squaredNorm() / (r * r));
                             sum_w += w;
                             sum += w * samples_.outward[k].dot(d);
                           });
  if (sum_w <= 0.0) return std::nullopt;
  return sum / sum_w;
}

template class SurfaceRim<2>;
template class SurfaceRim<3>;

}  // namespace amls
