#include "core/run/flow_test.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/deform/flow_deformation.hpp"
#include "core/util/process_memory.hpp"
#include "core/run/growth_limit.hpp"
#include "core/run/local_deforming_surface.hpp"
#include "core/run/ray_tracing_surface.hpp"
#include "core/run/settle.hpp"
#include "core/geometry/shapes.hpp"
#include "core/util/parameter_ranges.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

void validate(const FlowTestConfig& c) {
  check_range("--grid", c.grid, ranges::kFlowTestGridCells);
  check_range("--radius-factor", c.radius_factor, ranges::kRadiusFactor);
  check_range("--min-weight", c.min_weight, ranges::kMinWeight);
  check_range("--dt", c.dt, ranges::kTimeStep);
  check_range("--substeps", c.substeps, ranges::kSubsteps);
  check_range("--threads", c.threads, ranges::kThreads);
  check_range("--ray-samples", c.ray.samples_per_cell, ranges::kRaySamples);
  check_range("--cluster-threshold", c.ray.cluster_threshold, ranges::kClusterThreshold);
  if (c.resample.kind == ResamplePolicy::Kind::local && c.variant == FlowVariant::raytrace)
    throw std::invalid_argument(
        "--resample local needs --variant exact or interpolated: the ray-tracing baseline has no local resample");
}

// The points a test starts from, checked before they are made: `count` is
// what the grid implies, and the message names the largest grid that fits.
std::size_t initial_points(double count, const FlowTestConfig& config, int dimension) {
  if (count <= ranges::kPoints.max) return static_cast<std::size_t>(count);
  const double fitting = config.grid * std::pow(ranges::kPoints.max / count, 1.0 / (dimension - 1));
  throw std::invalid_argument("--grid " + std::to_string(config.grid) + " would start from " + format_number(count) +
                              " points, more than " + format_number(ranges::kPoints.max) + "; use --grid " +
                              std::to_string(static_cast<long long>(fitting)) + " or less");
}

// The work counters of one step, by loop.
void add_work(FlowTestReport& report, const StepStats& stats) {
  report.vertex_evaluations += stats.resample.vertices;
  report.crossings += stats.resample.crossings;
  report.root_evaluations += stats.resample.root_evaluations;
  report.failed_normal_fits += stats.normals.failed();
}

void add_work(FlowTestReport& report, const RayStepStats& stats) {
  report.sample_evaluations += stats.resample.samples;
  report.crossings += stats.resample.crossings;
  report.root_evaluations += stats.resample.root_evaluations;
  report.removed_clusters += stats.resample.removed;
  report.failed_normal_fits += stats.normals.failed();
}

void add_work(FlowTestReport& report, const LocalStepStats& stats) {
  report.vertex_evaluations += stats.resample.resample.vertices;
  report.crossings += stats.resample.resample.crossings;
  report.root_evaluations += stats.resample.resample.root_evaluations;
  report.failed_normal_fits += stats.resample.normals.failed();
}

// Whether a step that the policy let resample did: a local step only where strained.
bool resampled(const StepStats&) { return true; }
bool resampled(const RayStepStats&) { return true; }
bool resampled(const LocalStepStats& stats) { return stats.resample.flagged_cells > 0; }

// The local loop as run_flow drives a loop: each step deforms, then resamples where strained.
template <int D>
class LocalFlowLoop {
 public:
  LocalFlowLoop(const Grid<D>& grid, const AmlsParameters& parameters, Variant variant, int threads,
                double strain_limit)
      : surface_(grid, parameters, variant, threads, flow_resample_options(strain_limit)) {}
  void set_points(PointSet<D> points) { surface_.set_points(std::move(points)); }
  LocalStepStats resample_only() { return surface_.resample_all(); }
  LocalStepStats step(const Deformation<D>& deformation, double t0, double t1, bool) {
    return surface_.step(deformation, t0, t1);
  }
  const PointSet<D>& points() const { return surface_.points(); }
  const Grid<D>& grid() const { return surface_.grid(); }
  ThreadPool& pool() { return surface_.pool(); }
  AmlsSurface<D> fitted_surface() { return surface_.fitted_surface(); }

 private:
  LocalDeformingSurface<D> surface_;
};

// Runs a loop (DeformingSurface, RayTracingSurface or LocalFlowLoop) from t = 0 to `period`,
// starting from one resampling of the exact shape.
template <int D, typename Loop>
void run_flow(Loop& loop, std::shared_ptr<const VelocityField<D>> field, double period, const FlowTestConfig& config,
              const FlowProgress& progress, FlowTestReport& report) {
  const FlowDeformation<D> flow(std::move(field), config.substeps);
  loop.resample_only();
  report.points_initial = report.points_max = loop.points().size();
  report.steps_planned = static_cast<std::size_t>(std::llround(period / config.dt));
  decltype(loop.resample_only().timings) timings;  // the loop's own phase struct, summed over the steps
  for (std::size_t k = 0; k < report.steps_planned; ++k) {
    const double t0 = period * static_cast<double>(k) / static_cast<double>(report.steps_planned);
    const double t1 = period * static_cast<double>(k + 1) / static_cast<double>(report.steps_planned);
    // The paper's loop resamples within the step, before deforming.
    const bool resample = policy_resamples(config.resample, k, loop, report.quality_seconds);
    const auto stats = loop.step(flow, t0, t1, resample);
    report.resamples += resample && resampled(stats) ? 1 : 0;
    timings += stats.timings;
    report.points_processed += stats.points_before;
    add_work(report, stats);
    report.steps = k + 1;
    const std::size_t n = loop.points().size();
    report.points_max = std::max(report.points_max, n);
    if (progress) progress(k + 1, report.steps_planned, t1, n);
    if (n == 0) {
      report.broken = true;
      report.status_reason = "the point set vanished at step " + std::to_string(k + 1);
      break;
    }
    if (grew_past_limit(n, report.points_initial)) {
      report.broken = true;
      report.status_reason = growth_breakdown(k + 1);
      break;
    }
  }
  report.timings = timings.phases();
  report.points_final = loop.points().size();
}

// Measures the final surface (whichever loop made it: the same surface by the
// same code) and returns the run with the final points, which carry their
// pseudo-normals: the best normals the surface has.
template <int D, typename Measure>
FlowTestRun<D> finish(FlowTestReport& report, const AmlsSurface<D>& surface, Measure&& measure) {
  if (!surface.points().empty()) report.spacing_h = spacing_stats(surface.points(), surface.grid().spacing());
  ThreadPool pool(report.config.threads);
  const RayScan scan = measure(surface, pool, report);
  if (!report.broken && !scan.closed) {
    report.broken = true;
    report.status_reason = (report.dimension == 2 ? "the final curve is not one closed curve: "
                                                   : "the final surface is not closed: ") +
                           scan.reason;
  }
  report.peak_memory_mib = peak_memory_mib();
  PointSet<D> out = surface.points();
  if (surface.pseudo_normals().size() == out.size()) out.normals = surface.pseudo_normals();
  return {report, std::move(out)};
}

Variant grid_variant(FlowVariant variant) {
  return variant == FlowVariant::interpolated ? Variant::interpolated : Variant::exact;
}

// One flow test: the shape sampled at spacing h/2, carried by the field over
// [0, period], then measured against itself by `measure` (which fills the
// report's error figures and returns the closedness scan).
template <int D, typename Sample, typename Measure>
FlowTestRun<D> run_flow_test(const char* test, const FlowTestConfig& config, std::shared_ptr<const VelocityField<D>> field,
                             double period, Sample&& sample, Measure&& measure, const FlowProgress& progress) {
  validate(config);
  FlowTestReport report;
  report.test = test;
  report.dimension = D;
  report.config = config;
  const Grid<D> grid = Grid<D>::unit(config.grid);
  AmlsParameters parameters;
  parameters.radius_factor = config.radius_factor;
  parameters.min_weight = config.min_weight;
  parameters.bias_correction = config.bias_correction;
  parameters.keep_rims = config.keep_rims;
  if (config.variant == FlowVariant::raytrace) {
    RayTracingSurface<D> loop(grid, parameters, config.ray, config.threads);
    loop.set_points(sample(0.5 * grid.spacing()));
    run_flow<D>(loop, std::move(field), period, config, progress, report);
    return finish<D>(report, loop.amls_surface(), measure);
  }
  if (config.resample.kind == ResamplePolicy::Kind::local) {
    LocalFlowLoop<D> loop(grid, parameters, grid_variant(config.variant), config.threads, config.strain_limit);
    loop.set_points(sample(0.5 * grid.spacing()));
    run_flow<D>(loop, std::move(field), period, config, progress, report);
    return finish<D>(report, loop.fitted_surface(), measure);
  }
  DeformingSurface<D> loop(grid, parameters, grid_variant(config.variant), config.threads);
  loop.set_points(sample(0.5 * grid.spacing()));
  run_flow<D>(loop, std::move(field), period, config, progress, report);
  if (!loop.points().empty()) loop.refresh_normals();
  return finish<D>(report, loop.surface(), measure);
}

}  // namespace

const char* to_string(FlowVariant variant) {
  switch (variant) {
    case FlowVariant::exact: return "exact";
    case FlowVariant::interpolated: return "interpolated";
    case FlowVariant::raytrace: return "raytrace";
  }
  return "?";
}

FlowVariant parse_flow_variant(const std::string& name) {
  if (name == "exact") return FlowVariant::exact;
  if (name == "interpolated") return FlowVariant::interpolated;
  if (name == "raytrace") return FlowVariant::raytrace;
  throw std::invalid_argument("unknown variant '" + name + "' (expected exact, interpolated or raytrace)");
}

FlowTestRun<2> run_vortex_test(const FlowTestConfig& config, const FlowProgress& progress) {
  const Vec<2> center(0.5, 0.75);
  const double radius = 0.15;
  auto sample = [&](double spacing) {
    return sample_circle(center, radius, initial_points(std::ceil(2.0 * std::numbers::pi * radius / spacing), config, 2));
  };
  auto measure = [&](const AmlsSurface<2>& surface, ThreadPool& pool, FlowTestReport& report) {
    const CircleError error = circle_l1_error(surface, center, radius, pool);
    report.l1_error = error.l1;
    return error.scan;
  };
  return run_flow_test<2>("vortex", config, std::make_shared<SingleVortex>(8.0), 8.0, sample, measure, progress);
}

FlowTestRun<3> run_enright_test(const FlowTestConfig& config, const FlowProgress& progress) {
  const Vec<3> center(0.35, 0.35, 0.35);
  const double radius = 0.15;
  auto sample = [&](double spacing) {
    const double area = 4.0 * std::numbers::pi * radius * radius;
    return sample_sphere(center, radius, initial_points(std::ceil(area / (spacing * spacing)), config, 3));
  };
  auto measure = [&](const AmlsSurface<3>& surface, ThreadPool& pool, FlowTestReport& report) {
    const SphereError error = sphere_volume_error(surface, center, radius, pool);
    report.volume_loss = (error.exact_volume - error.volume) / error.exact_volume;
    report.symmetric_difference = error.symmetric_difference;
    report.relative_symmetric_difference = error.symmetric_difference / error.exact_volume;
    return error.scan;
  };
  return run_flow_test<3>("enright", config, std::make_shared<EnrightField>(3.0), 3.0, sample, measure, progress);
}

}  // namespace amls
