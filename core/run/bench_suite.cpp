#include "core/run/bench_suite.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/deform/flow_deformation.hpp"
#include "core/geometry/shapes.hpp"
#include "core/run/drag_bench.hpp"
#include "core/run/flow_test.hpp"
#include "core/util/process_memory.hpp"

namespace amls {

namespace {

BenchCase from_flow_test(const std::string& name, const FlowTestReport& r) {
  BenchCase c;
  c.name = name;
  c.points = r.points_max;
  c.points_processed = r.points_processed;
  c.timings = r.timings;
  c.peak_memory_mib = r.peak_memory_mib;
  c.threads = r.config.threads;
  char text[160];
  if (r.dimension == 2) {
    std::snprintf(text, sizeof text, "L1 error %.3g, %s", r.l1_error, r.broken ? "broken" : "ok");
  } else {
    std::snprintf(text, sizeof text, "volume loss %.2f %%, %s", 100.0 * r.volume_loss, r.broken ? "broken" : "ok");
  }
  c.result = text;
  return c;
}

// The case `make` builds, with its run measured.
BenchSpec measured(std::string name, std::function<BenchCase()> make) {
  return {name, [make = std::move(make)] {
            ParallelStopwatch clock;
            BenchCase c = make();
            c.run = clock.lap();
            return c;
          }};
}

std::string sphere_step_name(std::size_t points) {
  return "3D sphere step, " + std::to_string(points / 1000) + "k points";
}

std::string drag_name(std::size_t points, DragResample mode, bool regions) {
  const std::string size =
      points >= 1000000 ? std::to_string(points / 1000000) + "M" : std::to_string(points / 1000) + "k";
  return "drag " + size + " " + to_string(mode) + (regions ? " regions" : "");
}

BenchCase bench_drag(std::size_t points, DragResample mode, bool regions, int threads) {
  reset_peak_memory();
  DragBenchConfig config;
  config.points = points;
  config.threads = threads;
  config.resample = mode;
  config.regions = regions;
  const DragBenchReport r = run_drag_bench(config);
  BenchCase c;
  c.name = drag_name(points, mode, regions);
  c.points = r.points_initial;
  c.points_processed = r.points_initial * r.step_seconds.size();
  c.timings = r.timings.phases();
  c.peak_memory_mib = peak_memory_mib();
  c.threads = threads;
  char text[640];
  std::snprintf(text, sizeof text,
                "%zu steps: %.1f ms median (%.1f ms CPU, all threads), %.1f ms max per step, %.0f points resampled per "
                "step; after: spacing "
                "%.2f/%.2f/%.2f h (min/median/max), exact shape to surface %.2g/%.2g h (mean/max), %zu holes in %zu "
                "probes; exact shape %.2g h from the step-by-step one",
                r.step_seconds.size(), r.median_ms(), r.cpu_median_ms(), r.max_ms(), r.mean_resampled(),
                r.spacing_h.min, r.spacing_h.median, r.spacing_h.max, r.exact_to_surface_mean_h,
                r.exact_to_surface_max_h, r.holes, r.probes, r.rest_map_drift_h);
  c.result = text;
  if (mode == DragResample::local) {
    std::snprintf(text, sizeof text,
                  "; the drag's end maps the points exactly in %.0f ms (before it, exact shape to surface %.2g/%.2g h)",
                  1e3 * r.finish_seconds, r.interpolated_to_surface_mean_h, r.interpolated_to_surface_max_h);
    c.result += text;
  }
  c.figures = {{"step_ms_median", r.median_ms()},
               {"step_cpu_ms_median", r.cpu_median_ms()},
               {"step_ms_max", r.max_ms()},
               {"points_resampled_per_step", r.mean_resampled()},
               {"spacing_h_min", r.spacing_h.min},
               {"spacing_h_median", r.spacing_h.median},
               {"spacing_h_max", r.spacing_h.max},
               {"exact_to_surface_mean_h", r.exact_to_surface_mean_h},
               {"exact_to_surface_max_h", r.exact_to_surface_max_h},
               {"holes", static_cast<double>(r.holes)},
               {"rest_map_drift_h", r.rest_map_drift_h},
               {"steps_serial_share", r.steps_parallel.serial_share()}};
  if (mode == DragResample::local) {
    c.figures.emplace_back("finish_ms", 1e3 * r.finish_seconds);
    c.figures.emplace_back("interpolated_to_surface_mean_h", r.interpolated_to_surface_mean_h);
    c.figures.emplace_back("interpolated_to_surface_max_h", r.interpolated_to_surface_max_h);
  }
  return c;
}

}  // namespace

BenchCase bench_sphere_step(std::size_t points, int threads) {
  reset_peak_memory();
  const double radius = 0.3;
  const Vec<3> center(0.5, 0.5, 0.5);
  // A grid-resampled sphere has about 0.83 area / h^2 points (measured: the
  // HAVECLOSEPOINT rule keeps about 0.83 of the edge crossings' density).
  const double h = std::sqrt(0.83 * 4.0 * std::numbers::pi * radius * radius / static_cast<double>(points));
  DeformingSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{}, Variant::exact, threads);
  surface.set_points(sample_sphere(center, radius, points));
  surface.resample_only();
  const FlowDeformation<3> rotation(std::make_shared<RigidRotation<3>>(center, 1.0, Vec<3>::UnitZ()), 1);
  ParallelStopwatch clock;
  const StepStats stats = surface.step(rotation, 0.0, 0.01);
  const ParallelLap step = clock.lap();
  BenchCase c;
  c.name = sphere_step_name(points);
  c.points = c.points_processed = stats.points_before;
  c.timings = stats.timings.phases();
  c.peak_memory_mib = peak_memory_mib();
  c.threads = threads;
  c.result = std::to_string(stats.points_after) + " points after, h = " + std::to_string(h);
  c.figures = {{"step_serial_share", step.serial_share()}};
  // Where the step's serial seconds are, phase by phase.
  for (const PhaseTime& phase : stats.serial.phases()) c.figures.emplace_back("serial_s_" + phase.phase, phase.seconds);
  return c;
}

std::vector<BenchSpec> bench_suite(int threads) {
  std::vector<BenchSpec> specs;
  for (const FlowVariant variant : {FlowVariant::exact, FlowVariant::interpolated}) {
    const std::string name = std::string("2D vortex 512^2 ") + to_string(variant);
    specs.push_back(measured(name, [name, variant, threads] {
                       FlowTestConfig vortex;
                       vortex.grid = 512;
                       vortex.threads = threads;
                       vortex.variant = variant;
                       reset_peak_memory();
                       return from_flow_test(name, run_vortex_test(vortex).report);
                     }));
  }
  for (const std::size_t n : {50000u, 200000u, 1000000u})
    specs.push_back(measured(sphere_step_name(n), [n, threads] { return bench_sphere_step(n, threads); }));
  for (const std::size_t n : {200000u, 1000000u}) {
    for (const DragResample mode : {DragResample::always, DragResample::local})
      specs.push_back(
          measured(drag_name(n, mode, false), [n, mode, threads] { return bench_drag(n, mode, false, threads); }));
    // The same drag by two region handles: what a region costs against a point handle.
    specs.push_back(measured(drag_name(n, DragResample::local, true),
                             [n, threads] { return bench_drag(n, DragResample::local, true, threads); }));
  }
  const std::string enright_name = "3D Enright 128^3 exact";
  specs.push_back(measured(enright_name, [enright_name, threads] {
                     FlowTestConfig enright;
                     enright.grid = 128;
                     enright.threads = threads;
                     reset_peak_memory();
                     return from_flow_test(enright_name, run_enright_test(enright).report);
                   }));
  return specs;
}

}  // namespace amls
