#include "app/editor/sampling_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/point_index.hpp"

namespace amls::editor {

template <int D>
SamplingQuality sampling_quality(const PointSet<D>& points, double h) {
  SamplingQuality quality;
  const std::size_t n = points.size();
  if (n < 2) return quality;
  PointIndex<D> index;
  index.build(points.positions, points.positions.front(), 2.0 * h);
  quality.spacing_h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<D>& p = points.positions[i];
    double nearest2 = std::numeric_limits<double>::infinity();
    auto consider = [&](std::uint32_t id, const Vec<D>& q) {
      if (id != i) nearest2 = std::min(nearest2, (q - p).squaredNorm());
    };
    // Widen the search until some other point is found; once the search box
    // would hold more cells than there are points, scan them all instead.
    for (double reach = 2.0 * h; nearest2 == std::numeric_limits<double>::infinity(); reach *= 4.0) {
      if (std::pow(reach / h, D) > static_cast<double>(n)) {
        for (std::size_t j = 0; j < n; ++j) consider(static_cast<std::uint32_t>(j), points.positions[j]);
        break;
      }
      index.for_each_within(p, reach, consider);
    }
    quality.spacing_h[i] = std::sqrt(nearest2) / h;
  }
  std::vector<double> sorted = quality.spacing_h;
  std::sort(sorted.begin(), sorted.end());
  quality.stats = SpacingStats{sorted.front(), sorted[n / 2], sorted.back()};
  return quality;
}

template SamplingQuality sampling_quality<2>(const PointSet<2>&, double);
template SamplingQuality sampling_quality<3>(const PointSet<3>&, double);

}  // namespace amls::editor
