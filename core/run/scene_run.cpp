#include "core/run/scene_run.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/deform/mls_deformation.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/geometry/shapes.hpp"
#include "core/util/stopwatch.hpp"
#include "core/io/surface_samples.hpp"

namespace amls {

namespace {

// A run is broken when its point set vanishes or grows past this many times its start.
constexpr double kMaxGrowth = 20.0;

template <int D>
PointSet<D> from_3d(PointSet<3> points) {
  if constexpr (D == 2) {
    return to_2d(points);
  } else {
    return points;
  }
}

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
  options.threads = threads;
  try {
    return load_surface_samples(scene.shape.resolved_file, options);
  } catch (const std::exception& e) {
    throw std::runtime_error(scene.path + ": shape.path: " + e.what());
  }
}

// Undefined F at the probes, and the largest |F| / h at the others.
template <int D>
void probe(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& probes, std::size_t& holes, double& max_h) {
  holes = 0;
  max_h = 0.0;
  for (const Vec<D>& x : probes) {
    const Evaluation<D> e = surface.evaluate(x);
    if (!e.defined) {
      ++holes;
      continue;
    }
    max_h = std::max(max_h, std::abs(e.value) / surface.grid().spacing());
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

template <int D>
SceneRunReport run_scene(const Scene<D>& scene, const SceneRunOptions& options, const FrameSink<D>& frames,
                         const SceneProgress& progress, const FrameSink<D>& exact) {
  if (options.threads < 1) throw std::invalid_argument("--threads must be at least 1");
  if (!(options.tracers_per_point >= 1.0))
    throw std::invalid_argument("tracers per point must be at least 1, got " + std::to_string(options.tracers_per_point));
  scene.history.validate();
  Stopwatch wall;
  SceneRunReport report;
  report.dimension = D;
  report.scene = scene.path;
  report.name = scene.name;
  report.h = scene.h();
  report.radius_factor = scene.radius_factor;
  report.variant = scene.variant;
  report.kind = scene.kind;
  report.alpha = scene.alpha;
  report.resample = options.resample;
  report.policy = options.policy;
  report.threads = options.threads;
  report.stages = scene.history.stages.size();
  report.steps_planned = scene.history.total_steps();
  if (options.max_steps > 0) report.steps_planned = std::min(report.steps_planned, options.max_steps);

  SceneShapeSamples<D> shape = sample_scene_shape(scene, options.tracers_per_point, options.threads);
  report.shape_source = shape.source;
  report.warnings = shape.warnings;
  PointSet<D> tracers = std::move(shape.tracers);
  report.tracers = tracers.size();
  const auto stride = static_cast<std::size_t>(std::max(1.0, std::round(options.tracers_per_point / 4.0)));
  auto probes = [&] {
    std::vector<Vec<D>> out;
    for (std::size_t i = 0; i < tracers.size(); i += stride) out.push_back(tracers.positions[i]);
    return out;
  };
  report.probes = (tracers.size() + stride - 1) / stride;

  const Grid<D> grid = resampling_grid(shape.points, scene.h(), scene.radius_factor);
  report.grid_origin.template head<D>() = grid.origin();
  DeformingSurface<D> surface(grid, AmlsParameters{scene.radius_factor}, scene.variant, options.threads);
  report.points_initial = report.points_min = report.points_max = shape.points.size();
  surface.set_points(std::move(shape.points));

  std::vector<double> medians;
  // Measures the frame of `step` and hands it on. With resampling, only a
  // resample's frame counts in the run's spacing statistics: they describe
  // the resampler's points, not how far the deformation spread them since.
  auto frame = [&](std::size_t step, SceneStepRecord& record) {
    Stopwatch clock;
    const PointSet<D>& points = surface.points();
    record.step = step;
    record.points = points.size();
    const std::vector<double> spacings = nearest_neighbour_spacings(points, report.h);
    record.spacing_h = spacing_stats_of(spacings);
    record.spacing_below = static_cast<std::size_t>(std::lower_bound(spacings.begin(), spacings.end(), 0.3) - spacings.begin());
    record.spacing_above = static_cast<std::size_t>(spacings.end() - std::upper_bound(spacings.begin(), spacings.end(), 1.5));
    const bool counted = !options.resample || record.resampled;
    if (counted) {
      report.spacing_points += spacings.size();
      report.spacing_below += record.spacing_below;
      report.spacing_above += record.spacing_above;
    }
    if (counted && points.size() >= 2) {
      report.spacing_h.min = report.frames_measured == 0 ? record.spacing_h.min
                                                         : std::min(report.spacing_h.min, record.spacing_h.min);
      report.spacing_h.max = std::max(report.spacing_h.max, record.spacing_h.max);
      medians.push_back(record.spacing_h.median);
      ++report.frames_measured;
    }
    report.points_min = std::min(report.points_min, points.size());
    report.points_max = std::max(report.points_max, points.size());
    report.measure_seconds += clock.lap();
    if (frames) frames(step, points);
  };
  auto mark_broken = [&](std::size_t step, const std::string& why) {
    if (report.broken) return;
    report.broken = true;
    report.broken_at_step = step;
    report.status_reason = why;
  };

  ThreadPool& pool = surface.pool();
  // With resampling, before step `step` (and after the last): resamples S(P)
  // if the policy asks, and makes the frame. False if the resample is empty.
  auto settle = [&](std::size_t step, SceneStepRecord& record) {
    Stopwatch clock;
    record.resampled = options.policy.resample_now(step, surface.points(), grid.spacing(), pool);
    report.quality_seconds += clock.lap();
    if (record.resampled) {
      const StepStats stats = surface.resample_only();
      record.timings = stats.timings;
      record.failed_normal_fits = stats.normals.failed();
      ++report.resamples;
    }
    frame(step, record);
    return !surface.points().empty();
  };
  SceneStepRecord record;
  if (!options.resample) frame(0, record);
  for (std::size_t k = 0; k < report.steps_planned; ++k) {
    const HistoryStep<D> step = scene.history.step(k);
    record.stage = step.stage;
    if (options.resample && !settle(k, record)) {
      report.per_step.push_back(record);
      mark_broken(k, "the resampled point set is empty at step " + std::to_string(k) +
                         ": the surface has no zero crossing on the grid");
      break;
    }
    report.per_step.push_back(record);
    const MlsDeformation<D> deformation(step.from, step.to, scene.kind, scene.alpha);
    const StepStats stats = surface.step(deformation, 0.0, 1.0, false);
    report.per_step.back().timings += stats.timings;
    report.timings += report.per_step.back().timings;
    Stopwatch clock;
    deformation.apply(tracers, pool);
    report.tracer_seconds += clock.lap();
    report.affine_fallbacks += deformation.fallbacks();
    report.steps = k + 1;
    record = SceneStepRecord{};
    record.stage = step.stage;
    if (!options.resample) {
      const NormalStats normals = surface.refresh_normals();
      record.failed_normal_fits = normals.failed();
      Stopwatch probe_clock;
      record.probed = true;
      probe(surface.surface(), probes(), record.holes, record.probe_max_h);
      report.measure_seconds += probe_clock.lap();
      frame(k + 1, record);
      if (record.holes > 0)
        mark_broken(k + 1, "the surface broke at step " + std::to_string(k + 1) + ": F is undefined at " +
                               std::to_string(record.holes) + " of " + std::to_string(report.probes) +
                               " probes of the exact shape (the points there are more than about 1.3 Delta apart)");
      if (k + 1 == report.steps_planned) report.per_step.push_back(record);
    }
    if (progress) progress(k + 1, report.steps_planned, surface.points().size());
    const std::size_t n = surface.points().size();
    if (static_cast<double>(n) > kMaxGrowth * static_cast<double>(report.points_initial)) {
      mark_broken(k + 1, "the point set grew past 20 times its start at step " + std::to_string(k + 1));
      break;
    }
  }
  if (options.resample && !report.broken) {
    settle(report.steps, record);  // an empty final point set is flagged below
    report.timings += record.timings;
    report.per_step.push_back(record);
  }
  report.points_final = surface.points().size();

  // The final surface against the exact shape.
  Stopwatch clock;
  if (!surface.points().empty()) {
    surface.refresh_normals();
    probe(surface.surface(), probes(), report.final_holes, report.final_probe_max_h);
    report.distance_to_exact_h = nearest_distance_stats(surface.points().positions, tracers.positions, report.h);
    report.exact_to_points_h = nearest_distance_stats(tracers.positions, surface.points().positions, report.h);
  }
  if (report.final_holes > 0 && !options.resample)
    mark_broken(report.steps, "the final surface does not cover the exact shape: F is undefined at " +
                                  std::to_string(report.final_holes) + " of " + std::to_string(report.probes) +
                                  " probes");
  if (surface.points().empty()) mark_broken(report.steps, "the final point set is empty");
  report.measure_seconds += clock.lap();
  if (!medians.empty()) {
    std::sort(medians.begin(), medians.end());
    report.spacing_h.median = medians[medians.size() / 2];
  }
  if (report.affine_fallbacks > 0)
    report.warnings.push_back("the affine fit fell back to similarity at " + std::to_string(report.affine_fallbacks) +
                              " point evaluations (nearly collinear or coplanar handles)");
  if (exact) exact(report.steps, tracers);
  report.wall_seconds = wall.lap();
  return report;
}

template SceneShapeSamples<2> sample_scene_shape<2>(const Scene<2>&, double, int);
template SceneShapeSamples<3> sample_scene_shape<3>(const Scene<3>&, double, int);
template SceneRunReport run_scene<2>(const Scene<2>&, const SceneRunOptions&, const FrameSink<2>&,
                                     const SceneProgress&, const FrameSink<2>&);
template SceneRunReport run_scene<3>(const Scene<3>&, const SceneRunOptions&, const FrameSink<3>&,
                                     const SceneProgress&, const FrameSink<3>&);

}  // namespace amls
