#include "core/run/scene_samples.hpp"

#include <cmath>
#include <stdexcept>

#include "core/geometry/shapes.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/surface_samples.hpp"

namespace amls {

namespace {

// The built-in shape at `spacing`; `density` multiplies an explicit point count.
template <int D>
PointSet<D> sample_builtin(const SceneShape<D>& s, double spacing, double density) {
  auto scaled = [&](std::size_t count) {
    return static_cast<std::size_t>(std::llround(static_cast<double>(count) * density));
  };
  if constexpr (D == 2) {
    switch (s.type) {
      case ShapeType::circle:
        return sample_circle(s.center, s.radius,
                             s.points > 0 ? scaled(s.points) : circle_points_for_spacing(s.radius, spacing));
      case ShapeType::ellipse:
        return sample_ellipse(s.center, s.semi_axes, spacing);
      case ShapeType::rounded_box:
        return sample_rounded_box(s.center, s.half_extents, s.radius, spacing);
      default:
        break;
    }
  } else {
    switch (s.type) {
      case ShapeType::sphere:
        return sample_sphere(s.center, s.radius,
                             s.points > 0 ? scaled(s.points) : sphere_points_for_spacing(s.radius, spacing));
      case ShapeType::torus:
        return sample_torus(s.center, s.major_radius, s.minor_radius, spacing);
      case ShapeType::rounded_box:
        return sample_rounded_box(s.center, s.half_extents, s.radius, spacing);
      default:
        break;
    }
  }
  throw std::logic_error(std::string("shape ") + to_string(s.type) + " has no sampler in " + std::to_string(D) + "D");
}

template <int D>
SurfaceSamples load_file_shape(const Scene<D>& scene, double spacing, int threads) {
  SurfaceSampleOptions options;
  options.spacing = spacing;
  options.normal_radius = scene.radius_factor * scene.h();
  options.dimension = D;
  options.estimate_normals = scene.shape.estimate_normals;
  options.threads = threads;
  try {
    return load_surface_samples(scene.shape.resolved_file, options);
  } catch (const std::exception& e) {
    throw std::runtime_error(scene.path + ": shape.path: " + e.what());
  }
}

}  // namespace

template <int D>
SceneShapeSamples<D> sample_scene_shape(const Scene<D>& scene, double tracers_per_point, int threads) {
  SceneShapeSamples<D> out;
  const double spacing = scene.sample_spacing();
  // Tracers: f times as many points, so the spacing shrinks by f along a curve, by sqrt(f) over a surface.
  const double divisor = D == 2 ? tracers_per_point : std::sqrt(tracers_per_point);
  if (scene.shape.type != ShapeType::file) {
    out.points = sample_builtin<D>(scene.shape, spacing, 1.0);
    out.source = std::string(to_string(scene.shape.type)) + " of " + std::to_string(out.points.size()) + " points";
    if (tracers_per_point > 0.0) out.tracers = sample_builtin<D>(scene.shape, spacing / divisor, tracers_per_point);
  } else {
    SurfaceSamples samples = load_file_shape(scene, spacing, threads);
    if (samples.dimension != D)
      throw std::runtime_error(scene.path + ": shape.path: " + scene.shape.resolved_file + " holds a " +
                               std::to_string(samples.dimension) + "D shape, but the scene's dimension is " +
                               std::to_string(D));
    out.points = from_3d<D>(std::move(samples.points));
    out.source = samples.source;
    out.warnings = std::move(samples.warnings);
    if (tracers_per_point > 0.0) {
      if (is_mesh_file(scene.shape.resolved_file)) {
        out.tracers = from_3d<D>(load_file_shape(scene, spacing / divisor, threads).points);
      } else {
        out.tracers = out.points;
        out.warnings.push_back(scene.shape.resolved_file +
                               ": a point set cannot be sampled more densely, so its own points stand for the exact "
                               "shape (distances to it include the input's spacing)");
      }
    }
  }
  if (out.points.empty()) throw std::runtime_error(scene.path + ": shape: the initial shape has no points");
  return out;
}

template SceneShapeSamples<2> sample_scene_shape<2>(const Scene<2>&, double, int);
template SceneShapeSamples<3> sample_scene_shape<3>(const Scene<3>&, double, int);

}  // namespace amls
