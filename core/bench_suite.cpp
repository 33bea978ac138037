#include "core/bench_suite.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/flow_deformation.hpp"
#include "core/flow_test.hpp"
#include "core/process_memory.hpp"
#include "core/shapes.hpp"

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

}  // namespace

BenchCase bench_sphere_step(std::size_t points, int threads) {
  reset_peak_memory();
  const double radius = 0.3;
  const Vec<3> center(0.5, 0.5, 0.5);
  // A grid-resampled sphere has about area / h^2 points.
  const double h = std::sqrt(4.0 * std::numbers::pi * radius * radius / static_cast<double>(points));
  DeformingSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{}, Variant::exact, threads);
  surface.set_points(sample_sphere(center, radius, points));
  surface.resample_only();
  const FlowDeformation<3> rotation(std::make_shared<RigidRotation<3>>(center, 1.0, Vec<3>::UnitZ()), 1);
  const StepStats stats = surface.step(rotation, 0.0, 0.01);
  BenchCase c;
  c.name = "3D sphere step, " + std::to_string(points / 1000) + "k points";
  c.points = c.points_processed = stats.points_before;
  c.timings = stats.timings.phases();
  c.peak_memory_mib = peak_memory_mib();
  c.threads = threads;
  c.result = std::to_string(stats.points_after) + " points after, h = " + std::to_string(h);
  return c;
}

std::vector<BenchCase> run_bench_suite(int threads, const std::function<void(const BenchCase&)>& finished) {
  std::vector<BenchCase> cases;
  auto add = [&](BenchCase c) {
    cases.push_back(std::move(c));
    if (finished) finished(cases.back());
  };
  FlowTestConfig vortex;
  vortex.grid = 512;
  vortex.threads = threads;
  for (const FlowVariant variant : {FlowVariant::exact, FlowVariant::interpolated}) {
    vortex.variant = variant;
    reset_peak_memory();
    add(from_flow_test(std::string("2D vortex 512^2 ") + to_string(variant), run_vortex_test(vortex).report));
  }
  for (const std::size_t n : {50000u, 200000u, 1000000u}) add(bench_sphere_step(n, threads));
  FlowTestConfig enright;
  enright.grid = 128;
  enright.threads = threads;
  reset_peak_memory();
  add(from_flow_test("3D Enright 128^3 exact", run_enright_test(enright).report));
  return cases;
}

}  // namespace amls
