#include <doctest/doctest.h>

#include <string>

#include "core/run/bench_suite.hpp"
#include "core/geometry/shapes.hpp"
#include "core/run/drag_bench.hpp"

using namespace amls;

TEST_CASE("bench: one step on a sampled sphere keeps about the requested number of points and times every phase") {
  const BenchCase c = bench_sphere_step(5000, 2);
  CHECK(c.points > 3500);
  CHECK(c.points < 7000);
  CHECK(seconds_of(c.timings, "normals") > 0.0);
  CHECK(seconds_of(c.timings, "function") > 0.0);
  CHECK(seconds_of(c.timings, "resample") > 0.0);
  CHECK(c.points_per_second() > 0.0);
  CHECK(c.peak_memory_mib > 0.0);
  CHECK(c.threads == 2);
  // The step is mostly parallel loops, but not all of it (listing the cells' runs, the joins' prefix sums),
  // and its serial seconds are told phase by phase: each within its phase, all within the step.
  REQUIRE(c.figures.size() == 6);
  CHECK(c.figures[0].first == "step_serial_share");
  CHECK(c.figures[0].second > 0.0);
  CHECK(c.figures[0].second < 1.0);
  double serial_seconds = 0.0;
  for (std::size_t k = 1; k < c.figures.size(); ++k) {
    const std::string phase = c.figures[k].first.substr(std::string("serial_s_").size());
    CHECK(c.figures[k].first == "serial_s_" + phase);
    CHECK(c.figures[k].second >= 0.0);
    CHECK(c.figures[k].second <= seconds_of(c.timings, phase));
    serial_seconds += c.figures[k].second;
  }
  CHECK(serial_seconds > 0.0);
}

TEST_CASE("bench: a case of the suite measures its whole run and the part of it in parallel loops") {
  for (BenchSpec& spec : bench_suite(1)) {
    if (spec.name != "3D sphere step, 50k points") continue;
    const BenchCase c = spec.run();
    // Set-up and step together outlast the step's phases; their loops are a part of the run.
    CHECK(c.run.wall > total_seconds(c.timings));
    CHECK(c.run.parallel > 0.0);
    CHECK(c.run.parallel < c.run.wall);
    CHECK(c.run.serial_share() > 0.0);
    CHECK(c.run.serial_share() < 1.0);
    return;
  }
  FAIL("the suite has no 50k sphere step");
}

TEST_CASE("bench: the drag, resampled always or locally, keeps the surface whole and near the exact shape") {
  double always_resampled = 0.0;
  for (const DragResample mode : {DragResample::always, DragResample::local}) {
    DragBenchConfig config;
    config.points = 6000;
    config.threads = 2;
    config.steps = 6;
    config.pull_h = 3.0;  // hard enough that the local policy resamples near the pulled handle
    config.tracers = 5000;
    config.resample = mode;
    const DragBenchReport r = run_drag_bench(config);
    INFO(std::string(to_string(mode)) << ": distance mean " << r.exact_to_surface_mean_h << " max " << r.exact_to_surface_max_h
                         << ", spacing " << r.spacing_h.min << "/" << r.spacing_h.max << ", resampled per step "
                         << r.mean_resampled());
    CHECK(r.step_seconds.size() == 6);
    CHECK(r.step_cpu_seconds.size() == 6);
    CHECK(r.steps_parallel.parallel > 0.0);
    CHECK(r.steps_parallel.parallel <= r.steps_parallel.wall);
    // Always maps step by step, as its tracers do; local maps from rest states, a new one at each
    // resample, and its tracers follow them: near the step-by-step shape (0.057 h here).
    if (mode == DragResample::always) CHECK(r.rest_map_drift_h == 0.0);
    if (mode == DragResample::local) CHECK(r.rest_map_drift_h < 0.5);
    CHECK(r.holes == 0);
    CHECK(r.exact_to_surface_max_h < 0.1);
    CHECK(r.spacing_h.min > 0.3);
    CHECK(r.spacing_h.max < 2.0);
    CHECK(r.mean_resampled() > 0.0);
    if (mode == DragResample::always) {
      CHECK(r.mean_resampled() > 0.8 * static_cast<double>(r.points_initial));
      always_resampled = r.mean_resampled();
    }
    // A pull this hard strains much of this small sphere, and a region is resampled whole once it passes the limit.
    if (mode == DragResample::local) CHECK(r.mean_resampled() < 0.7 * always_resampled);
  }
}

TEST_CASE("bench: the drag by two region handles keeps the surface whole, near the exact shape, and lifts its top cap") {
  DragBenchConfig config;
  config.points = 6000;
  config.threads = 2;
  config.steps = 6;
  config.pull_h = 3.0;
  config.tracers = 5000;
  config.resample = DragResample::local;
  config.regions = true;
  const DragBenchReport r = run_drag_bench(config);
  INFO("distance mean " << r.exact_to_surface_mean_h << " max " << r.exact_to_surface_max_h << ", spacing "
                        << r.spacing_h.min << "/" << r.spacing_h.max << ", drift " << r.rest_map_drift_h);
  CHECK(r.step_seconds.size() == 6);
  CHECK(r.holes == 0);
  CHECK(r.exact_to_surface_max_h < 0.1);
  CHECK(r.spacing_h.min > 0.3);
  CHECK(r.spacing_h.max < 2.0);
  CHECK(r.rest_map_drift_h < 0.5);
}

TEST_CASE("bench: the drag's regions are the caps about the poles, the bottom pinned and the top pulled") {
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 2000);
  std::vector<Vec<3>> bottom, top;
  for (const Vec<3>& p : sphere.positions) (p.z() < 0.5 ? bottom : top).push_back(p);
  const auto a = std::make_shared<const PointRegion<3>>(bottom, 0.01);
  const auto b = std::make_shared<const PointRegion<3>>(top, 0.01);
  const std::vector<RegionHandle<3>> regions = drag_regions({a, b}, 0.02, 3);
  REQUIRE(regions.size() == 2);
  CHECK(regions[0].pinned);
  CHECK(regions[0].motion == RegionMotion<3>{});
  CHECK_FALSE(regions[1].pinned);
  CHECK((regions[1].motion.translation - Vec<3>(0.0, 0.0, 0.06)).norm() < 1e-15);
}
