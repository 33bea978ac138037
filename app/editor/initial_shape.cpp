#include "app/editor/initial_shape.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "app/editor/scene_start.hpp"
#include "core/io/file_format.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/shape_opening.hpp"
#include "core/util/parameter_ranges.hpp"

namespace amls::editor {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

void check_builtin(double radius, std::size_t points, double spacing, std::size_t least) {
  require(radius > 0.0 && std::isfinite(radius), "shape radius must be a positive number");
  require(points >= least, "a built-in shape needs at least " + std::to_string(least) + " points");
  require(spacing > 0.0 && std::isfinite(spacing), "grid spacing h must be a positive number");
}

InitialShape with_editor_policy(InitialShape shape) {
  if (shape.points.size() >= kLocalResamplingFrom) shape.settings.policy = ResamplePolicy::parse("local");
  return shape;
}

// A built-in shape as a scene without a history: the default shape of a
// Scene<D> (a circle in 2D, a sphere in 3D), sampled as `amls deform` would.
template <int D>
InitialShape builtin(double radius, std::size_t points, double spacing) {
  check_builtin(radius, points, spacing, D + 1);
  Scene<D> scene;
  scene.shape.radius = radius;
  scene.shape.points = points;
  scene.grid_spacing = spacing;
  return with_editor_policy(start_from_scene(scene, 1));
}

// A point-set file opened on its own, as a scene would name it.
template <int D>
SceneShape<D> file_shape(const std::string& path, bool estimate_normals) {
  SceneShape<D> shape;
  shape.type = ShapeType::file;
  shape.file = path;
  shape.resolved_file = path;
  shape.estimate_normals = estimate_normals;
  return shape;
}

// One resampling at the shape's h and with its supports, as `amls resample`
// would do it, and its coverage of the points.
template <int D>
void measure_coverage_of(InitialShape& shape, const PointSet<D>& points, int threads) {
  PointSetResampling options;
  options.threads = threads;
  options.spacing = shape.settings.spacing;
  options.radius_factor = shape.settings.radius_factor;
  options.widen_support = shape.settings.widen_support;
  const ResampledPointSet<D> resampled = resample_point_set(points, options);
  const Coverage& c = resampled.coverage;
  shape.coverage = "resampled at h: " + c.summary();
  if (resampled.widening.widened_points > 0)
    shape.coverage += "; support widened at " + std::to_string(resampled.widening.widened_points) + " of " +
                      std::to_string(points.size()) + " points where the input is sparse (up to " +
                      format_number(resampled.widening.widest) + " Delta)";
  shape.coverage_loss = c.clear_loss();
  if (shape.coverage_loss) shape.coverage = shape.name + ": " + c.loss_message();
}

}  // namespace

InitialShape make_circle(double radius, std::size_t points, double spacing) {
  return builtin<2>(radius, points, spacing);
}

InitialShape make_sphere(double radius, std::size_t points, double spacing) {
  return builtin<3>(radius, points, spacing);
}

InitialShape default_shape(int dimension) {
  return dimension == 3 ? make_sphere(1.0, 10000, 0.04) : make_circle(1.0, 250, 0.024);
}

InitialShape load_shape_file(const std::string& path, ThreadPool& pool, const LoadStep& step, bool estimate_normals) {
  // The road's steps, then the coverage.
  constexpr int kSteps = kShapeOpeningSteps + 1;
  ShapeOpening opening;
  opening.resampling.threads = pool.threads();
  opening.estimate_normals = estimate_normals;
  // The h the Surface panel shows and Save Scene writes, before the normals and a mesh's samples are made
  // with it, so that a saved session replays from the same samples.
  opening.spacing_digits = 3;
  if (step) opening.step = [&](const char* name, int index, int) { step(name, index, kSteps); };
  OpenedShape opened = open_shape_file(path, opening, pool);
  InitialShape shape;
  shape.source = opened.dimension == 2 ? ShapeSource(file_shape<2>(path, estimate_normals))
                                       : ShapeSource(file_shape<3>(path, estimate_normals));
  shape.settings.spacing = opened.spacing.h;
  shape.settings.radius_factor = opening.resampling.radius_factor;
  // Real data is often sparse in places: widen there, as `amls resample` does.
  shape.settings.widen_support = true;
  shape.points = std::move(opened.points);
  shape.name = std::filesystem::path(path).filename().string();
  shape.warnings = std::move(opened.warnings);
  if (opened.closed_mesh) shape.closed_mesh = std::make_shared<const TriangleMesh>(std::move(*opened.closed_mesh));
  shape.opened = path + ": " + opened.source + "; h = " + format_number(shape.settings.spacing) + ": " +
                 opened.spacing.reason;
  pool.poll_cancel();
  if (step) step("measuring the coverage at h", kShapeOpeningSteps, kSteps);
  try {
    if (opened.dimension == 2)
      measure_coverage_of(shape, to_2d(shape.points), pool.threads());
    else
      measure_coverage_of(shape, shape.points, pool.threads());
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return shape;
}

InitialShape load_initial_shape(const std::string& path, ThreadPool& pool, const LoadStep& step,
                                bool estimate_normals) {
  if (lower_extension(path) == ".json") {
    if (step) step("reading the scene", 0, 1);
    return with_editor_policy(load_scene_start(path, pool.threads()));
  }
  return with_editor_policy(load_shape_file(path, pool, step, estimate_normals));
}

InitialShape load_initial_shape(const std::string& path, int threads) {
  ThreadPool pool(threads);
  return load_initial_shape(path, pool);
}

}  // namespace amls::editor
