#include "app/picture_input.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <variant>

#include "core/io/file_format.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/surface_samples.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/scene_state.hpp"
#include "core/surface/curve_tracing.hpp"
#include "core/surface/metrics.hpp"
#include "core/util/parameter_ranges.hpp"
#include "render/point_data.hpp"

namespace amls {

namespace {

// Meshes without a given spacing are sampled at their bounding box's diagonal over this.
constexpr double kMeshSamplesPerDiagonal = 200.0;

// Every point drawable: the renderer would skip the others silently, but a file with
// a broken point is an error worth telling.
void require_drawable(const PointSet<3>& points, const std::string& path) {
  if (points.empty()) throw std::runtime_error(path + ": holds no points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec<3>& p = points.positions[i];
    const Vec<3>& n = points.normals[i];
    if (!p.allFinite())
      throw std::runtime_error(path + ": point " + std::to_string(i) + " has a non-finite position (" +
                               format_number(p[0]) + ", " + format_number(p[1]) + ", " + format_number(p[2]) + ")");
    if (!n.allFinite() || n.squaredNorm() == 0.0)
      throw std::runtime_error(path + ": point " + std::to_string(i) + " has " +
                               (n.allFinite() ? "a zero normal" : "a non-finite normal") + " (" + format_number(n[0]) +
                               ", " + format_number(n[1]) + ", " + format_number(n[2]) + ")");
  }
}

// The MLS curve of a 2D point set: its AMLS surface on `grid`, traced.
std::vector<glm::vec2> mls_curve(const PointSet<2>& points, const Grid<2>& grid, const AmlsParameters& parameters,
                                 int threads) {
  ThreadPool pool(threads);
  AmlsSurface<2> surface(grid, parameters);
  surface.set_points(points);
  surface.hash_points();
  surface.update_normals(pool);
  std::vector<glm::vec2> out;
  const TracedCurve curve = trace_curve(surface, pool);
  out.reserve(2 * curve.segments.size());
  for (const CurveSegment& s : curve.segments) {
    out.emplace_back(static_cast<float>(s.a[0]), static_cast<float>(s.a[1]));
    out.emplace_back(static_cast<float>(s.b[0]), static_cast<float>(s.b[1]));
  }
  return out;
}

void add_quality(Picture& picture) {
  picture.quality = picture.dimension == 2 ? nearest_neighbour_spacing_per_point(to_2d(picture.points), picture.h)
                                           : nearest_neighbour_spacing_per_point(picture.points, picture.h);
  if (picture.quality.empty()) picture.quality.assign(picture.points.size(), std::nan(""));  // a single point
}

template <int D>
Picture scene_picture(const Scene<D>& scene, const PictureInputOptions& options) {
  const std::size_t total = scene.history.total_steps();
  const std::size_t step = options.step.value_or(0) == kFinalStep ? total : options.step.value_or(0);
  if (step > total)
    throw std::invalid_argument(scene.path + ": --step " + std::to_string(step) + " is past the scene's end: it has " +
                                std::to_string(total) + " steps (--step last draws its final state)");
  SceneState<D> state = scene_state_after(scene, step, options.threads, options.progress);
  Picture picture;
  picture.dimension = D;
  picture.h = state.grid.spacing();
  picture.warnings = std::move(state.warnings);
  if constexpr (D == 2) {
    if (options.curve) picture.curve = mls_curve(state.points, state.grid, state.parameters, options.threads);
  }
  for (const Vec<D>& handle : state.handles) picture.handles.push_back(to_vec3<D>(handle));
  if constexpr (D == 2)
    picture.points = to_3d(state.points);
  else
    picture.points = std::move(state.points);
  picture.description = "scene " + (scene.name.empty() ? scene.path : scene.name) + " (" + std::to_string(D) +
                        "D) after " + std::to_string(step) + " of " + std::to_string(total) +
                        " steps: " + std::to_string(picture.points.size()) + " points, h = " + format_number(picture.h);
  return picture;
}

Picture file_picture(const std::string& path, const PictureInputOptions& options) {
  if (options.spacing != 0.0) check_range("--spacing", options.spacing, ranges::kSpacing);
  Picture picture;
  SurfaceSampleOptions sampling;
  sampling.dimension = options.dimension;
  sampling.threads = options.threads;
  SurfaceSamples samples;
  if (is_mesh_file(path)) {
    double h = options.spacing;
    if (h == 0.0 && options.grid > 0) {
      PointSetResampling given;
      given.grid = options.grid;
      h = choose_spacing(read_mesh(path).vertices, given).h;
    }
    if (h == 0.0) {
      const TriangleMesh mesh = read_mesh(path);
      Vec<3> lo = Vec<3>::Constant(INFINITY), hi = Vec<3>::Constant(-INFINITY);
      for (const Vec<3>& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      const double diagonal = mesh.vertices.empty() ? 0.0 : (hi - lo).norm();
      if (!(diagonal > 0.0) || !std::isfinite(diagonal))
        throw std::runtime_error(path + ": the mesh has no extent to sample (give --spacing)");
      h = diagonal / kMeshSamplesPerDiagonal;
    }
    sampling.spacing = h;
    samples = load_surface_samples(path, sampling);
    picture.h = h;
  } else {
    LoadedPointSet loaded = read_point_set(path, options.dimension);
    if (loaded.points.empty()) throw std::runtime_error(path + ": holds no points");
    // Positions first: the spacing estimate and the normal estimation need them finite.
    for (std::size_t i = 0; i < loaded.points.size(); ++i)
      if (!loaded.points.positions[i].allFinite())
        throw std::runtime_error(path + ": point " + std::to_string(i) + " has a non-finite position");
    double h = 0.0;
    try {
      PointSetResampling given;
      given.spacing = options.spacing;
      given.grid = options.grid;
      given.recorded_spacing = loaded.spacing;
      h = loaded.dimension == 2 ? choose_spacing(to_2d(loaded.points).positions, given).h
                                : choose_spacing(loaded.points.positions, given).h;
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + ": no h (" + std::string(e.what()) + "); give --spacing");
    }
    picture.h = h;
    if (loaded.has_normals) {
      samples.dimension = loaded.dimension;
      samples.points = std::move(loaded.points);
      samples.source = "point set of " + std::to_string(samples.points.size()) + " points with normals";
      samples.warnings = std::move(loaded.warnings);
    } else {
      sampling.dimension = loaded.dimension;
      sampling.normal_radius = options.radius_factor * h;
      samples = load_surface_samples(path, sampling);  // reads it again, estimating normals over Delta
    }
  }
  require_drawable(samples.points, path);
  picture.dimension = samples.dimension;
  picture.points = std::move(samples.points);
  picture.warnings = std::move(samples.warnings);
  picture.description = path + ": " + samples.source + " (" + std::to_string(picture.dimension) +
                        "D), h = " + format_number(picture.h) + (options.spacing > 0.0 || options.grid > 0 ? "" : " (estimated)");
  if (options.curve && picture.dimension == 2) {
    const PointSet<2> flat = to_2d(picture.points);
    picture.curve = mls_curve(flat, resampling_grid(flat, picture.h, options.radius_factor),
                              AmlsParameters{options.radius_factor}, options.threads);
  }
  return picture;
}

}  // namespace

Picture load_picture(const std::string& path, const PictureInputOptions& options) {
  check_range("--radius-factor", options.radius_factor, ranges::kRadiusFactor);
  Picture picture;
  if (lower_extension(path) == ".json") {
    if (options.spacing != 0.0)
      throw std::invalid_argument(path +
                                  ": a scene has its own grid; --spacing and --grid are for point sets and meshes");
    if (options.dimension != 0)
      throw std::invalid_argument(path + ": a scene has its own dimension; --dim is for point sets");
    const AnyScene scene = read_scene(path);
    picture = std::visit([&](const auto& s) { return scene_picture(s, options); }, scene);
  } else {
    if (options.step)
      throw std::invalid_argument(path + ": --step is for scenes (.json), not for point sets or meshes");
    picture = file_picture(path, options);
  }
  if (options.quality) add_quality(picture);
  return picture;
}

}  // namespace amls
