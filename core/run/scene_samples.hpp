#pragma once
// A scene's initial shape as points: a built-in shape sampled at the scene's
// spacing, or a point-set or mesh file read (and a mesh sampled) through
// core/io/surface_samples.hpp. The tracers that stand for the exact deformed
// shape in `amls deform` (core/run/scene_run.hpp) are the same shape sampled
// more densely.
#include <string>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "core/run/scene.hpp"

namespace amls {

// The initial shape's samples (and, with a positive `tracers_per_point`, the
// tracers) of a scene.
template <int D>
struct SceneShapeSamples {
  PointSet<D> points;
  PointSet<D> tracers;
  std::string source;
  std::vector<std::string> warnings;
};

// Throws std::runtime_error naming the scene file for a shape file that
// cannot be read, is empty or has the wrong dimension.
template <int D>
SceneShapeSamples<D> sample_scene_shape(const Scene<D>& scene, double tracers_per_point, int threads = 1);

extern template SceneShapeSamples<2> sample_scene_shape<2>(const Scene<2>&, double, int);
extern template SceneShapeSamples<3> sample_scene_shape<3>(const Scene<3>&, double, int);

}  // namespace amls
