#include "core/run/drag_bench.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>

#include "core/deform/mls_deformation.hpp"
#include "core/geometry/shapes.hpp"
#include "core/run/local_deforming_surface.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

const Vec<3> kCenter(0.5, 0.5, 0.5);
constexpr double kRadius = 0.3;
// The region variant's caps: the sphere's points within this of a pole.
constexpr double kCapRadius = 0.05;

// The handles of one step, of either kind.
struct DragHandles {
  std::vector<Vec<3>> points;
  std::vector<RegionHandle<3>> regions;
};

std::shared_ptr<const PointRegion<3>> cap(const PointSet<3>& sphere, const Vec<3>& pole, double reach) {
  std::vector<Vec<3>> members;
  for (const Vec<3>& p : sphere.positions)
    if ((p - pole).norm() <= kCapRadius) members.push_back(p);
  return std::make_shared<const PointRegion<3>>(std::move(members), reach);
}

// |F| / h at the tracers, and where F is undefined there.
void measure_tracers(const AmlsSurface<3>& surface, const std::vector<Vec<3>>& tracers, ThreadPool& pool,
                     DragBenchReport& report) {
  struct Partial {
    double sum = 0.0;
    double max = 0.0;
    std::size_t defined = 0;
    std::size_t holes = 0;
  };
  std::vector<Partial> partial(static_cast<std::size_t>(pool.threads()));
  const double h = surface.grid().spacing();
  pool.parallel_for(tracers.size(), [&](std::size_t begin, std::size_t end, int block) {
    Partial p;
    for (std::size_t i = begin; i < end; ++i) {
      const Evaluation<3> e = surface.evaluate(tracers[i]);
      if (!e.defined) {
        ++p.holes;
        continue;
      }
      const double d = std::abs(e.value) / h;
      p.sum += d;
      p.max = std::max(p.max, d);
      ++p.defined;
    }
    // A block may run in pieces (under a cancellation check): add each piece to the block's total.
    Partial& total = partial[static_cast<std::size_t>(block)];
    total.sum += p.sum;
    total.max = std::max(total.max, p.max);
    total.defined += p.defined;
    total.holes += p.holes;
  });
  Partial total;
  for (const Partial& p : partial) {
    total.sum += p.sum;
    total.max = std::max(total.max, p.max);
    total.defined += p.defined;
    total.holes += p.holes;
  }
  report.probes = tracers.size();
  report.holes = total.holes;
  report.exact_to_surface_max_h = total.max;
  report.exact_to_surface_mean_h = total.defined > 0 ? total.sum / static_cast<double>(total.defined) : 0.0;
}

double median_of_ms(std::vector<double> seconds) {
  if (seconds.empty()) return 0.0;
  std::sort(seconds.begin(), seconds.end());
  return 1000.0 * seconds[seconds.size() / 2];
}

// The process's CPU time so far, all threads.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

const char* to_string(DragResample mode) { return mode == DragResample::always ? "always" : "local"; }

double DragBenchReport::median_ms() const { return median_of_ms(step_seconds); }

double DragBenchReport::cpu_median_ms() const { return median_of_ms(step_cpu_seconds); }

double DragBenchReport::max_ms() const {
  return step_seconds.empty() ? 0.0 : 1000.0 * *std::max_element(step_seconds.begin(), step_seconds.end());
}

double DragBenchReport::mean_resampled() const {
  if (resampled.empty()) return 0.0;
  double sum = 0.0;
  for (const std::size_t n : resampled) sum += static_cast<double>(n);
  return sum / static_cast<double>(resampled.size());
}

std::vector<Vec<3>> drag_handles(const Vec<3>& center, double radius, double pull, std::size_t step) {
  return {center - radius * Vec<3>::UnitZ(), center + radius * Vec<3>::UnitX(), center + radius * Vec<3>::UnitY(),
          center + (radius + pull * static_cast<double>(step)) * Vec<3>::UnitZ()};
}

std::vector<RegionHandle<3>> drag_regions(const std::array<std::shared_ptr<const PointRegion<3>>, 2>& caps, double pull,
                                          std::size_t step) {
  RegionMotion<3> pulled;
  pulled.translation = pull * static_cast<double>(step) * Vec<3>::UnitZ();
  return {{caps[0], RegionMotion<3>{}, true}, {caps[1], pulled, false}};
}

DragBenchReport run_drag_bench(const DragBenchConfig& config) {
  DragBenchReport report;
  report.config = config;
  // As bench_sphere_step: a grid-resampled sphere has about 0.83 area / h^2 points.
  const double h = std::sqrt(0.83 * 4.0 * std::numbers::pi * kRadius * kRadius / static_cast<double>(config.points));
  report.h = h;
  const double pull = config.pull_h * h;
  const Grid<3> grid(Vec<3>::Zero(), h);
  PointSet<3> tracers = config.tracers > 0 ? sample_sphere(kCenter, kRadius, config.tracers) : PointSet<3>{};
  const PointSet<3> sphere = sample_sphere(kCenter, kRadius, config.points);
  std::array<std::shared_ptr<const PointRegion<3>>, 2> caps;
  if (config.regions)
    caps = {cap(sphere, kCenter - kRadius * Vec<3>::UnitZ(), h), cap(sphere, kCenter + kRadius * Vec<3>::UnitZ(), h)};
  auto handles = [&](std::size_t k) {
    return config.regions ? DragHandles{{}, drag_regions(caps, pull, k)}
                          : DragHandles{drag_handles(kCenter, kRadius, pull, k), {}};
  };
  auto deformation = [&](std::size_t k) {
    const DragHandles from = handles(k), to = handles(k + 1);
    return MlsDeformation<3>(from.points, to.points, from.regions, to.regions);
  };
  // The final points' quality, on a surface of their own, against the exact shape.
  auto measure = [&](const PointSet<3>& points, const PointSet<3>& exact_shape, ThreadPool& pool) {
    report.points_final = points.size();
    if (exact_shape.empty()) return;
    report.spacing_h = spacing_stats(points, h);
    AmlsSurface<3> surface(grid, AmlsParameters{});
    surface.set_points(points);
    surface.hash_points(pool);
    surface.update_normals(pool);
    measure_tracers(surface, exact_shape.positions, pool, report);
  };
  if (config.resample == DragResample::always) {
    DeformingSurface<3> surface(grid, AmlsParameters{}, Variant::exact, config.threads);
    surface.set_points(sphere);
    surface.resample_only();
    report.points_initial = surface.points().size();
    for (std::size_t k = 0; k < config.steps; ++k) {
      const MlsDeformation<3> map = deformation(k);
      ParallelStopwatch clock;
      const double cpu = cpu_seconds();
      const StepStats stats = surface.step(map, 0.0, 1.0);
      const ParallelLap lap = clock.lap();
      report.step_seconds.push_back(lap.wall);
      report.steps_parallel += lap;
      report.step_cpu_seconds.push_back(cpu_seconds() - cpu);
      report.resampled.push_back(stats.resample.inserted);
      report.timings += stats.timings;
      if (!tracers.empty()) map.apply(tracers, surface.pool());
    }
    surface.resample_only();
    measure(surface.points(), tracers, surface.pool());
  } else {
    LocalDeformingSurface<3> surface(grid, AmlsParameters{}, Variant::exact, config.threads);
    surface.set_points(sphere);
    surface.resample_all();
    report.points_initial = surface.points().size();
    // The exact shape of this loop: the tracers mapped exactly from the same
    // rest states as the points (a new one at every resample).
    PointSet<3> rest_tracers = tracers;
    DragHandles tracers_rest = handles(0);
    for (std::size_t k = 0; k < config.steps; ++k) {
      const MlsDeformation<3> map = deformation(k);
      ParallelStopwatch clock;
      const double cpu = cpu_seconds();
      const LocalStepStats stats = surface.step(map);
      const ParallelLap lap = clock.lap();
      report.step_seconds.push_back(lap.wall);
      report.steps_parallel += lap;
      report.step_cpu_seconds.push_back(cpu_seconds() - cpu);
      report.resampled.push_back(stats.resample.inserted);
      report.timings += stats.timings;
      if (tracers.empty()) continue;
      map.apply(tracers, surface.pool());
      if (surface.rest_handles() != tracers_rest.points || !same_places(surface.rest_regions(), tracers_rest.regions)) {
        MlsDeformation<3>(tracers_rest.points, surface.rest_handles(), tracers_rest.regions, surface.rest_regions())
            .apply(rest_tracers, surface.pool());
        tracers_rest = {surface.rest_handles(), surface.rest_regions()};
      }
    }
    const DragHandles end = handles(config.steps);
    MlsDeformation<3>(tracers_rest.points, end.points, tracers_rest.regions, end.regions)
        .apply(rest_tracers, surface.pool());
    for (std::size_t i = 0; i < tracers.size(); ++i)
      report.rest_map_drift_h =
          std::max(report.rest_map_drift_h, (rest_tracers.positions[i] - tracers.positions[i]).norm() / h);
    measure(surface.points(), rest_tracers, surface.pool());
    report.interpolated_to_surface_mean_h = report.exact_to_surface_mean_h;
    report.interpolated_to_surface_max_h = report.exact_to_surface_max_h;
    Stopwatch clock;
    const bool mapped = surface.map_exactly();
    report.finish_seconds = clock.lap();
    if (mapped) measure(surface.points(), rest_tracers, surface.pool());
  }
  return report;
}

}  // namespace amls
