#pragma once
// Sampling quality for the editor's display and Table 1: each point's distance
// to its nearest neighbour in units of h (about 0.5..1.5 after a resample;
// larger values show where the points thin out and the surface may break).
#include <vector>

#include "core/surface/metrics.hpp"

namespace amls::editor {

struct SamplingQuality {
  std::vector<double> spacing_h;  // per point, in the points' order
  SpacingStats stats;             // min, median, max of spacing_h
};

// Empty for fewer than two points. The points are shared among the pool's threads.
template <int D>
SamplingQuality sampling_quality(const PointSet<D>& points, double h, ThreadPool& pool);

extern template SamplingQuality sampling_quality<2>(const PointSet<2>&, double, ThreadPool&);
extern template SamplingQuality sampling_quality<3>(const PointSet<3>&, double, ThreadPool&);

}  // namespace amls::editor
