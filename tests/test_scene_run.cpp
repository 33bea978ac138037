#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "core/run/scene_run.hpp"

using namespace amls;

namespace {

Vec<2> polar(double r, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  return Vec<2>(r * std::cos(a), r * std::sin(a));
}

// A short clover: the unit circle of 250 points (spacing 0.025) grows four
// leaves in 8 steps, then a stem (a handle added beside the bottom notch: a
// new stage) in 8 more, on the clover2d scene's grid (h = 0.024, Delta = 3h).
Scene<2> short_clover() {
  Scene<2> scene;
  scene.shape.type = ShapeType::circle;
  scene.shape.points = 250;
  scene.grid_spacing = 0.024;
  std::vector<Vec<2>> start, leaves;
  for (double tip : {45.0, 135.0, 225.0, 315.0}) {
    start.push_back(polar(1.0, tip));
    leaves.push_back(polar(1.4, tip));
  }
  for (double notch : {0.0, 90.0, 180.0, 270.0}) {
    start.push_back(polar(1.0, notch));
    leaves.push_back(polar(0.5, notch));
  }
  scene.history.begin_stage(start);
  scene.history.add_target(leaves, 8);
  std::vector<Vec<2>> with_stem = leaves;
  with_stem.push_back(leaves.back());  // the bottom notch gets a second handle: a new stage
  with_stem[7] = polar(0.5, 270) + Vec<2>(0.1, 0);
  scene.history.begin_stage(with_stem);
  with_stem.back() = Vec<2>(0, -1.5);
  scene.history.add_target(with_stem, 8);
  return scene;
}

}  // namespace

TEST_CASE("scene run: with resampling the clover stays close to the exact deformed shape and evenly sampled") {
  const Scene<2> scene = short_clover();
  std::size_t frames = 0;
  SceneRunOptions options;
  options.tracers_per_point = 20;
  const SceneRunReport r = run_scene<2>(scene, options, [&](std::size_t, const PointSet<2>&) { ++frames; });
  CHECK(frames == 17);  // R_0 ... R_16
  CHECK(r.steps == 16);
  CHECK_FALSE(r.broken);
  CHECK(r.points_initial == 250);
  CHECK(r.distance_to_exact_h.mean < 0.5);
  CHECK(r.distance_to_exact_h.max < 2.0);
  for (const SceneStepRecord& s : r.per_step) {
    CHECK(s.spacing_h.min >= 0.3);
    CHECK(s.spacing_h.max <= 2.0);
  }
  // The band [0.3 h, 1.5 h] holds for all but a few points (the resampler leaves gaps of up to ~1.8 h).
  CHECK(static_cast<double>(r.spacing_above + r.spacing_below) < 0.01 * static_cast<double>(r.spacing_points));
  CHECK(r.spacing_h.median == doctest::Approx(1.0).epsilon(0.1));
}

TEST_CASE("scene run: auto resamples fewer times than there are steps and stays close to the exact shape") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 20;
  const SceneRunReport always = run_scene<2>(scene, options);
  options.policy = ResamplePolicy::parse("auto");
  std::size_t frames = 0;
  const SceneRunReport r = run_scene<2>(scene, options, [&](std::size_t, const PointSet<2>&) { ++frames; });
  CHECK(always.resamples == 17);  // R_0 ... R_16
  CHECK(frames == 17);            // a frame per step either way
  CHECK_FALSE(r.broken);
  CHECK(r.steps == 16);
  CHECK(r.resamples >= 2);  // R_0 and at least one the deformation called for
  CHECK(r.resamples < r.steps);
  CHECK(r.policy.to_string() == "auto");
  CHECK(r.quality_seconds > 0.0);  // the checks were measured (not their length: that is the machine's)
  // The records say which steps resampled; only those count in the spacing statistics.
  REQUIRE(r.per_step.size() == 17);
  CHECK(r.per_step.front().resampled);
  std::size_t resampled = 0, points = 0;
  for (const SceneStepRecord& s : r.per_step) {
    if (!s.resampled) continue;
    ++resampled;
    points += s.points;
    CHECK(s.spacing_h.min >= 0.3);
    CHECK(s.spacing_h.max <= 2.0);
  }
  CHECK(resampled == r.resamples);
  CHECK(r.frames_measured == r.resamples);
  CHECK(r.spacing_points == points);
  CHECK(r.spacing_h.median == doctest::Approx(1.0).epsilon(0.1));
  CHECK(r.distance_to_exact_h.mean < 0.5);  // the bound `always` is held to (docs/deform-results.md)
}

TEST_CASE("scene run: local resamples where strained, every frame counts, and stays close to the exact shape") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 20;
  const SceneRunReport always = run_scene<2>(scene, options);
  options.policy = ResamplePolicy::parse("local");
  std::size_t frames = 0;
  const SceneRunReport r = run_scene<2>(scene, options, [&](std::size_t, const PointSet<2>&) { ++frames; });
  CHECK_FALSE(r.broken);
  CHECK(r.steps == 16);
  CHECK(frames == 17);
  REQUIRE(r.per_step.size() == 17);
  CHECK(r.per_step.front().resampled);  // the start resamples the whole surface
  CHECK(r.resamples >= 2);              // and the clover's leaves strain it somewhere
  CHECK(r.frames_measured == 17);       // every frame is what the loop carries on with
  CHECK(r.final_holes == 0);
  MESSAGE("local: " << r.resamples << " resamples, distance to the exact shape mean " << r.distance_to_exact_h.mean
                    << " h, max " << r.distance_to_exact_h.max << " h (always " << always.distance_to_exact_h.mean
                    << ", " << always.distance_to_exact_h.max << ")");
  CHECK(r.distance_to_exact_h.mean < 0.5);  // the bound `always` is held to (docs/deform-results.md)
  CHECK(r.spacing_h.min >= 0.3);
  CHECK(r.spacing_h.max <= 2.0);
}

TEST_CASE("scene run: frames larger than the spacing sample are measured on it, within the whole frames' extremes") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 4;
  const SceneRunReport whole = run_scene<2>(scene, options);
  CHECK(whole.spacing_sampled_frames == 0);
  CHECK(whole.spacing_sample == SceneRunOptions::kDefaultSpacingSample);
  options.spacing_sample = 100;
  const SceneRunReport r = run_scene<2>(scene, options);
  REQUIRE(r.per_step.size() == whole.per_step.size());
  CHECK(r.spacing_sampled_frames == r.per_step.size());  // every frame has more than 100 points
  std::size_t measured = 0;
  for (std::size_t k = 0; k < r.per_step.size(); ++k) {
    const SceneStepRecord& sampled = r.per_step[k];
    const SceneStepRecord& all = whole.per_step[k];
    CHECK(sampled.points == all.points);  // the measure changes nothing of the run
    CHECK(all.spacing_measured == all.points);
    // About one point in 3 (ceil(points / 100)), by blocks of the grid.
    CHECK(sampled.spacing_measured > 30);
    CHECK(sampled.spacing_measured < all.points);
    if (sampled.resampled) measured += sampled.spacing_measured;  // the frames that count (`always`)
    // Each sampled point's spacing is its exact one, so the sample's extremes lie within the frame's.
    CHECK(sampled.spacing_h.min >= all.spacing_h.min);
    CHECK(sampled.spacing_h.max <= all.spacing_h.max);
    CHECK(sampled.spacing_below <= all.spacing_below);
    CHECK(sampled.spacing_above <= all.spacing_above);
  }
  CHECK(r.spacing_points == measured);
  CHECK(r.distance_to_exact_h.mean == whole.distance_to_exact_h.mean);
}

TEST_CASE("scene run: the end's two-way distances measure from a block sample of about max_probes points of each set") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 4;
  const SceneRunReport whole = run_scene<2>(scene, options);
  REQUIRE(whole.distance_to_exact_h.count == whole.points_final);
  REQUIRE(whole.exact_to_points_h.count == whole.tracers);
  options.max_probes = 40;
  const SceneRunReport r = run_scene<2>(scene, options);
  REQUIRE(r.points_final == whole.points_final);  // the measure changes nothing of the run
  REQUIRE(r.points_final > 40);
  // The points of blocks 8 h wide, one block in ceil(size / 40): a few blocks' points.
  CHECK(r.distance_to_exact_h.count < whole.distance_to_exact_h.count / 2);
  CHECK(r.distance_to_exact_h.count > 0);
  CHECK(r.exact_to_points_h.count < whole.exact_to_points_h.count / 2);
  CHECK(r.exact_to_points_h.count > 0);
  // Each sampled distance is one of the whole run's, so the sample's largest is at most theirs.
  CHECK(r.distance_to_exact_h.max <= whole.distance_to_exact_h.max);
  CHECK(r.exact_to_points_h.max <= whole.exact_to_points_h.max);
  CHECK(r.distance_to_exact_h.mean > 0.0);
}

TEST_CASE("scene run: every:K resamples steps 0, K, 2K, ... and the final point set when it falls on one") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 1;
  options.max_steps = 10;
  options.policy = ResamplePolicy::parse("every:4");
  const SceneRunReport r = run_scene<2>(scene, options);
  CHECK_FALSE(r.broken);
  REQUIRE(r.per_step.size() == 11);
  for (const SceneStepRecord& s : r.per_step) CHECK(s.resampled == (s.step % 4 == 0));
  CHECK(r.resamples == 3);  // steps 0, 4, 8; the final state (10) keeps its deformed points
}

TEST_CASE("scene run: without resampling the stem thins out and the report names the step the surface broke") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.resample = false;
  options.tracers_per_point = 20;
  const SceneRunReport r = run_scene<2>(scene, options);
  CHECK(r.broken);
  CHECK(r.broken_at_step > 8);  // the leaves alone do not break it; the stem does
  CHECK(r.broken_at_step <= 16);
  CHECK(r.status_reason.find("broke at step " + std::to_string(r.broken_at_step)) != std::string::npos);
  CHECK(r.points_final == 250);
  // Before the break every probe of the exact shape was covered.
  for (const SceneStepRecord& s : r.per_step)
    if (s.probed && s.step < r.broken_at_step) CHECK(s.holes == 0);
  CHECK(r.per_step.back().spacing_h.max > 3.0);
}

TEST_CASE("scene run: under local, the end's sampled probes read F of the whole final surface") {
  const Scene<2> scene = short_clover();
  SceneRunOptions options;
  options.tracers_per_point = 4;  // every tracer a probe of the whole run
  options.max_steps = 6;
  options.policy = ResamplePolicy::parse("local");
  options.max_probes = 0;
  const SceneRunReport whole = run_scene<2>(scene, options);
  REQUIRE_FALSE(whole.final_probes_sampled);
  REQUIRE(whole.probes == whole.tracers);
  options.max_probes = 40;
  const SceneRunReport r = run_scene<2>(scene, options);
  REQUIRE(r.points_final == whole.points_final);  // the measure changes nothing of the run
  CHECK(r.final_probes_sampled);
  CHECK(r.probes > 0);
  CHECK(r.probes < whole.probes);
  // The sampled probes are some of the whole run's, and the part of the points
  // fitted gives F there as all of them do: their largest |F| is at most the whole's.
  CHECK(r.final_holes == whole.final_holes);
  CHECK(r.final_probe_max_h <= whole.final_probe_max_h + 1e-9);
  CHECK(r.final_probe_max_h > 0.0);
}
