#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "core/run/scene_state.hpp"
#include "scene_fixtures.hpp"

using namespace amls;
using amls::test::pulled_circle;

TEST_CASE("scene state after K steps is frame K of the scene's run, with the handles of that moment") {
  const Scene<2> scene = pulled_circle(4);
  PointSet<2> frame2;
  SceneRunOptions options;
  options.max_steps = 2;
  run_scene<2>(scene, options, [&](std::size_t k, const PointSet<2>& points) {
    if (k == 2) frame2 = points;
  });
  const SceneState<2> state = scene_state_after(scene, 2);
  CHECK(state.step == 2);
  CHECK(state.total_steps == 4);
  REQUIRE(state.points.size() == frame2.size());
  CHECK(state.points.positions == frame2.positions);
  CHECK(state.grid.spacing() == 0.024);
  CHECK(state.parameters.radius_factor == 3.0);
  REQUIRE(state.handles.size() == 4);
  CHECK((state.handles[0] - 1.15 * Vec<2>(std::sqrt(0.5), std::sqrt(0.5))).norm() < 1e-12);  // halfway
}

TEST_CASE(
    "scene state after 0 steps is the resampled initial shape; after all steps, the handles are the last target") {
  const Scene<2> scene = pulled_circle(4);
  const SceneState<2> start = scene_state_after(scene, 0);
  REQUIRE(start.points.size() > 200);
  for (const Vec<2>& p : start.points.positions) CHECK(std::abs(p.norm() - 1.0) < 0.1 * 0.024);
  CHECK(start.handles == scene.history.stages[0].start);
  const SceneState<2> end = scene_state_after(scene, 4);
  CHECK(end.handles == scene.history.stages[0].targets.back().handles);
  // The diagonals were pulled out: the farthest point now lies well beyond the unit circle.
  double farthest = 0.0;
  for (const Vec<2>& p : end.points.positions) farthest = std::max(farthest, p.norm());
  CHECK(farthest > 1.15);
}

TEST_CASE("scene state past the history's end is a clear error") {
  const Scene<2> scene = pulled_circle(4);
  CHECK_THROWS_AS(scene_state_after(scene, 5), std::invalid_argument);
  CHECK_THROWS_AS(handles_after(scene.history, 5), std::out_of_range);
  CHECK(handles_after(DeformationHistory<2>{}, 0).empty());
}
