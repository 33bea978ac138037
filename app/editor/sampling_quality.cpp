#include "app/editor/sampling_quality.hpp"

#include <algorithm>

namespace amls::editor {

template <int D>
SamplingQuality sampling_quality(const PointSet<D>& points, double h, ThreadPool& pool) {
  SamplingQuality quality;
  quality.spacing_h = nearest_neighbour_spacing_per_point(points, h, pool);
  if (quality.spacing_h.empty()) return quality;
  // Min, median and max in linear time: a million points are sorted in about a tenth of a second.
  std::vector<double> work = quality.spacing_h;
  const auto middle = work.begin() + static_cast<std::ptrdiff_t>(work.size() / 2);
  std::nth_element(work.begin(), middle, work.end());
  const auto [low, high] = std::minmax_element(quality.spacing_h.begin(), quality.spacing_h.end());
  quality.stats = SpacingStats{*low, *middle, *high};
  return quality;
}

template SamplingQuality sampling_quality<2>(const PointSet<2>&, double, ThreadPool&);
template SamplingQuality sampling_quality<3>(const PointSet<3>&, double, ThreadPool&);

}  // namespace amls::editor
