#include "core/io/point_set_repair.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "core/geometry/point_index.hpp"
#include "core/io/point_set_io.hpp"
#include "core/surface/metrics.hpp"
#include "core/surface/normal_estimation.hpp"

namespace amls::detail {

namespace {

// Normals this close to unit length are kept as they are, bit for bit, so that
// a set written and read back is the same set; others are normalised.
constexpr double kUnitTolerance = 1e-12;
// Normals off by more than this were not meant to be unit (float storage is
// off by about 1e-7): worth a warning.
constexpr double kNormaliseWarning = 1e-4;
// The fit radius for a missing normal, in units of the set's median
// nearest-neighbour spacing: the paper's support Delta = 3h, with h about the
// sampling's spacing. Neighbours within twice that orient the fitted normal.
constexpr double kFitRadiusInSpacings = 3.0;

// Three significant digits, for distances in messages.
std::string rounded(double value) {
  std::ostringstream text;
  text << std::setprecision(3) << value;
  return text.str();
}

// Keeps the points whose `keep` flag is set, in their order, with their lines
// and their entries in `flags`.
void keep_points(RawPointFile& raw, const std::vector<std::uint8_t>& keep, std::vector<std::uint8_t>& flags) {
  if (raw.lines.empty() && raw.vertices.empty()) {
    raw.vertices.resize(keep.size());
    std::iota(raw.vertices.begin(), raw.vertices.end(), std::size_t{0});
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    raw.points.positions[kept] = raw.points.positions[i];
    raw.points.normals[kept] = raw.points.normals[i];
    if (i < raw.points.rim.size()) raw.points.rim[kept] = raw.points.rim[i];
    if (i < raw.lines.size()) raw.lines[kept] = raw.lines[i];
    if (i < raw.vertices.size()) raw.vertices[kept] = raw.vertices[i];
    if (i < flags.size()) flags[kept] = flags[i];
    ++kept;
  }
  raw.points.positions.resize(kept);
  raw.points.normals.resize(kept);
  if (!raw.points.rim.empty()) raw.points.rim.resize(kept);
  if (!raw.lines.empty()) raw.lines.resize(kept);
  if (!raw.vertices.empty()) raw.vertices.resize(kept);
  if (!flags.empty()) flags.resize(kept);
}

void drop_non_finite_points(RawPointFile& raw) {
  const std::size_t n = raw.points.size();
  std::vector<std::uint8_t> keep(n, 1), none;
  std::size_t dropped = 0, first = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (raw.points.positions[i].allFinite()) continue;
    keep[i] = 0;
    if (dropped++ == 0) first = i;
  }
  if (dropped == 0) return;
  const Vec<3>& p = raw.points.positions[first];
  raw.warnings.push_back(raw.path + ": " + std::to_string(dropped) +
                         " points with a non-finite coordinate were dropped (the first at " + raw.where(first) + ": " +
                         shortest(p.x()) + " " + shortest(p.y()) + " " + shortest(p.z()) + ")");
  keep_points(raw, keep, none);
}

// Points at exactly the position of an earlier one are merged into it; the
// earlier one takes the later one's normal if its own was unusable.
void merge_duplicates(RawPointFile& raw, std::vector<std::uint8_t>& unusable) {
  const std::size_t n = raw.points.size();
  const std::vector<Vec<3>>& p = raw.points.positions;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto before = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(p[a].data(), p[a].data() + 3, p[b].data(), p[b].data() + 3);
  };
  std::stable_sort(order.begin(), order.end(), before);
  std::vector<std::uint8_t> keep(n, 1);
  std::size_t merged = 0, first = n;
  for (std::size_t k = 0; k < n;) {
    const std::size_t kept = order[k];  // the earliest in the file: the sort is stable
    std::size_t end = k + 1;
    for (; end < n && p[order[end]] == p[kept]; ++end) {
      const std::size_t j = order[end];
      keep[j] = 0;
      ++merged;
      first = std::min(first, j);
      if (unusable[kept] && !unusable[j]) {
        raw.points.normals[kept] = raw.points.normals[j];
        unusable[kept] = 0;
      }
    }
    k = end;
  }
  if (merged == 0) return;
  raw.warnings.push_back(
      raw.path + ": " + std::to_string(merged) +
      " points repeat the exact position of an earlier point and were merged into it (the first at " +
      raw.where(first) + ")");
  keep_points(raw, keep, unusable);
}

template <int D>
Vec<D> in_d(const Vec<3>& v) {
  if constexpr (D == 2) {
    return Vec<2>(v.x(), v.y());
  } else {
    return v;
  }
}

// The median distance from a point to its nearest neighbour (the set has at
// least two points, no two at one position).
template <int D>
double median_spacing(const std::vector<Vec<D>>& positions) {
  Vec<D> lo = positions.front(), hi = positions.front();
  for (const Vec<D>& q : positions) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  // Measured from the lowest corner, in units of a first guess (the box's
  // diagonal spread over the points of a curve or surface), whatever the
  // coordinates' units and offset.
  PointSet<D> shifted;
  for (const Vec<D>& q : positions) shifted.positions.push_back(q - lo);
  const double n = static_cast<double>(positions.size());
  const double guess = (hi - lo).norm() / (D == 2 ? n : std::sqrt(n));
  const std::vector<double> spacings = nearest_neighbour_spacings<D>(shifted, guess);
  return spacings[spacings.size() / 2] * guess;
}

// Fits the normals flagged in `unusable` from their neighbours' positions and
// orients each to agree with the normals around it.
template <int D>
void estimate_unusable_normals(RawPointFile& raw, const std::vector<std::uint8_t>& unusable, std::size_t count) {
  const std::size_t n = raw.points.size();
  std::vector<Vec<D>> positions(n), normals(n);
  for (std::size_t i = 0; i < n; ++i) {
    positions[i] = in_d<D>(raw.points.positions[i]);
    normals[i] = in_d<D>(raw.points.normals[i]);
  }
  const double radius = kFitRadiusInSpacings * median_spacing<D>(positions);
  const double reach = 2.0 * radius;
  PointIndex<D> index;
  index.build(positions, positions.front(), reach);

  // The fits need only the points near the unusable ones.
  std::vector<std::uint32_t> local_of(n, UINT32_MAX);
  std::vector<std::size_t> global_of;
  auto include = [&](std::uint32_t id) {
    if (local_of[id] != UINT32_MAX) return;
    local_of[id] = static_cast<std::uint32_t>(global_of.size());
    global_of.push_back(id);
  };
  for (std::size_t i = 0; i < n; ++i)
    if (unusable[i]) index.for_each_within(positions[i], reach, [&](std::uint32_t id, const Vec<D>&) { include(id); });
  if (global_of.size() < static_cast<std::size_t>(D + 1))
    for (std::size_t i = 0; i < n; ++i) include(static_cast<std::uint32_t>(i));
  PointSet<D> local;
  for (const std::size_t i : global_of) local.positions.push_back(positions[i]);
  ThreadPool pool(1);
  estimate_normals<D>(local, radius, pool);

  // Where no neighbour has a normal, the fits' own orientation, turned to
  // agree with the given normals among the fitted points on the whole.
  double agreement = 0.0;
  for (std::size_t k = 0; k < global_of.size(); ++k)
    if (!unusable[global_of[k]]) agreement += local.normals[k].dot(normals[global_of[k]]);
  std::size_t alone = 0;
  for (std::size_t k = 0; k < global_of.size(); ++k) {
    const std::size_t i = global_of[k];
    if (!unusable[i]) continue;
    Vec<D> normal = local.normals[k];
    double vote = 0.0;
    index.for_each_within(positions[i], reach, [&](std::uint32_t j, const Vec<D>&) {
      if (!unusable[j]) vote += normal.dot(normals[j]);
    });
    if (vote == 0.0) {
      ++alone;
      vote = agreement;
    }
    if (vote < 0.0) normal = -normal;
    for (int a = 0; a < D; ++a) raw.points.normals[i][a] = normal[a];
  }
  std::size_t first = 0;
  while (!unusable[first]) ++first;
  std::string warning = raw.path + ": " + std::to_string(count) +
                        " points have a zero-length or non-finite normal (the first at " + raw.where(first) +
                        "); their normals were estimated from the neighbours within " + rounded(radius) +
                        " and oriented to agree with the neighbours' normals";
  if (alone > 0)
    warning += " (" + std::to_string(alone) + " have no neighbour with a normal within " + rounded(reach) +
               " and were oriented as the fits agree with the normals on the whole)";
  raw.warnings.push_back(warning);
}

}  // namespace

std::vector<std::uint8_t> prepare_points(RawPointFile& raw) {
  drop_non_finite_points(raw);
  const std::size_t n = raw.points.size();
  std::vector<std::uint8_t> unusable(n, 0);
  if (!raw.has_normals) return unusable;
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec<3>& normal = raw.points.normals[i];
    if (normal.allFinite() && !normal.isZero(0.0)) continue;
    normal.setZero();
    unusable[i] = 1;
    ++count;
  }
  if (n > 0 && count == n) {
    raw.has_normals = false;
    raw.warnings.push_back(raw.path + ": every normal is zero or not finite; read as a point set without normals");
    return std::vector<std::uint8_t>(n, 0);
  }
  std::size_t normalised = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec<3>& normal = raw.points.normals[i];
    const double length = normal.norm();
    if (unusable[i] || std::abs(length - 1.0) <= kUnitTolerance) continue;
    // A normal whose squared length overflows has a finite, non-zero norm from
    // Eigen's stableNorm; plain norm() would give inf.
    const double stable = std::isfinite(length) && length > 0.0 ? length : normal.stableNorm();
    normal /= stable;
    worst = std::max(worst, std::abs(stable - 1.0));
    ++normalised;
  }
  if (worst > kNormaliseWarning)
    raw.warnings.push_back(raw.path + ": " + std::to_string(normalised) +
                           " normals were not of unit length and were normalised (the farthest had length off by " +
                           shortest(worst) + ")");
  return unusable;
}

void repair_points(RawPointFile& raw, int dimension, std::vector<std::uint8_t> unusable) {
  merge_duplicates(raw, unusable);
  const auto count = static_cast<std::size_t>(std::count(unusable.begin(), unusable.end(), std::uint8_t{1}));
  if (count == 0) return;
  const std::size_t n = raw.points.size();
  if (n < static_cast<std::size_t>(dimension + 1)) {
    const auto first = static_cast<std::size_t>(std::find(unusable.begin(), unusable.end(), 1) - unusable.begin());
    fail(raw.path, raw.where(first) + ": zero-length or non-finite normal, and " + std::to_string(n) +
                       " points are too few to estimate it from neighbours");
  }
  try {
    if (dimension == 2) {
      estimate_unusable_normals<2>(raw, unusable, count);
    } else {
      estimate_unusable_normals<3>(raw, unusable, count);
    }
  } catch (const std::invalid_argument& e) {  // e.g. a spread too wide for the neighbour index's cells
    fail(raw.path, std::to_string(count) +
                       " points have a zero-length or non-finite normal, which cannot be "
                       "estimated: " +
                       e.what());
  }
}

}  // namespace amls::detail
