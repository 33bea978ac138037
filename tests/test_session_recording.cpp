#include <doctest/doctest.h>

#include "app/editor/session_recording.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

using Handles = std::vector<Vec<2>>;

SceneShape<2> circle_source() {
  SceneShape<2> s;
  s.type = ShapeType::circle;
  s.radius = 1.0;
  s.points = 250;
  return s;
}

// A step of the editor with resampling on: [R], D, R.
void editor_step(SessionRecording<2>& r, const Handles& from, const Handles& to, const SurfaceSettings& s,
                 bool resample_first) {
  if (resample_first) r.resampled(s);
  r.deformed(from, to, s);
  r.resampled(s);
}

}  // namespace

TEST_CASE("steps that continue each other share a stage - a changed handle set starts one") {
  SessionRecording<2> r(circle_source(), {});
  const SurfaceSettings s;
  const Handles a{{1, 0}}, b{{1.1, 0}}, c{{1.2, 0}};
  const Handles c2{{1.2, 0}, {0, 1}}, d2{{1.2, 0}, {0, 1.2}};
  editor_step(r, a, b, s, true);
  editor_step(r, b, c, s, false);
  editor_step(r, c2, d2, s, false);  // a handle was added
  const auto stages = r.history().stages;
  REQUIRE(stages.size() == 2);
  CHECK(stages[0].start == a);
  REQUIRE(stages[0].targets.size() == 2);
  CHECK(stages[0].targets[0].handles == b);
  CHECK(stages[0].targets[1].handles == c);
  CHECK(stages[1].start == c2);
  REQUIRE(stages[1].targets.size() == 1);
  CHECK(stages[1].targets[0].handles == d2);
  CHECK(stages[1].targets[0].steps == 1);
  CHECK(r.exact());
}

TEST_CASE("settings changed before the first step are the scene's - after it they spoil an exact replay") {
  SurfaceSettings s;
  SessionRecording<2> r(circle_source(), s);
  s.variant = Variant::interpolated;
  r.resampled(s);  // the variant toggled at once, before any step
  s.kind = MlsKind::affine;
  editor_step(r, {{1, 0}}, {{1.1, 0}}, s, false);
  CHECK(r.exact());
  CHECK(r.settings().variant == Variant::interpolated);
  CHECK(r.settings().kind == MlsKind::affine);

  s.variant = Variant::exact;
  r.resampled(s);  // toggled back after a step: R R
  CHECK(!r.exact());
  CHECK(r.inexact_reason().find("twice") != std::string::npos);
}

TEST_CASE("a session without resampling is replayed with --no-resample - switching it on spoils that") {
  SurfaceSettings s;
  s.resample = false;
  SessionRecording<2> r(circle_source(), s);
  r.deformed({{1, 0}}, {{1.1, 0}}, s);
  r.deformed({{1.1, 0}}, {{1.2, 0}}, s);
  CHECK(r.exact());
  CHECK(r.no_resample());
  r.resampled(s);
  CHECK(!r.exact());
}

TEST_CASE("under auto a step the policy left unresampled replays exactly, with the policy on the command line") {
  SurfaceSettings s;
  s.policy = ResamplePolicy::parse("auto");
  SessionRecording<2> r(circle_source(), s);
  CHECK(r.replay_arguments().empty());  // nothing decided yet
  r.resampled(s);
  r.deformed({{1, 0}}, {{1.1, 0}}, s);  // the policy kept these points: no resample
  r.deformed({{1.1, 0}}, {{1.2, 0}}, s);
  CHECK(r.exact());
  CHECK(r.settings().policy.to_string() == "auto");
  CHECK(r.replay_arguments() == "--resample auto");
  CHECK(recorded_scene(r, "/tmp/x.json", "x").description.find("`amls deform --resample auto` replays it") !=
        std::string::npos);

  s.policy = ResamplePolicy::parse("every:3");
  r.deformed({{1.2, 0}}, {{1.3, 0}}, s);
  CHECK(!r.exact());
  CHECK(r.inexact_reason().find("resample policy changed") != std::string::npos);
}

TEST_CASE("replay arguments: none under always, --no-resample without resampling, and switching it off spoils") {
  SurfaceSettings s;
  SessionRecording<2> always(circle_source(), s);
  editor_step(always, {{1, 0}}, {{1.1, 0}}, s, true);
  CHECK(always.replay_arguments().empty());
  s.resample = false;
  always.deformed({{1.1, 0}}, {{1.2, 0}}, s);
  CHECK(!always.exact());
  CHECK(always.inexact_reason().find("switched off") != std::string::npos);

  SessionRecording<2> never(circle_source(), s);
  never.deformed({{1, 0}}, {{1.1, 0}}, s);
  CHECK(never.replay_arguments() == "--no-resample");
}

TEST_CASE("a change of MLS kind or alpha after the first step spoils an exact replay") {
  SurfaceSettings s;
  SessionRecording<2> r(circle_source(), s);
  editor_step(r, {{1, 0}}, {{1.1, 0}}, s, true);
  s.alpha = 2.0;
  editor_step(r, {{1.1, 0}}, {{1.2, 0}}, s, false);
  CHECK(!r.exact());
}

TEST_CASE("the recorded scene holds the shape, the session's settings and one step per target") {
  SurfaceSettings s;
  s.spacing = 0.03;
  SessionRecording<2> r(circle_source(), s);
  CHECK_THROWS_WITH_AS(recorded_scene(r, "/tmp/x.json", "x"), doctest::Contains("nothing to save"), std::runtime_error);
  s.kind = MlsKind::affine;
  editor_step(r, {{1, 0}}, {{1.1, 0.5}}, s, true);
  const Scene<2> scene = recorded_scene(r, "/tmp/x.json", "session");
  CHECK(scene.name == "session");
  CHECK(scene.shape.type == ShapeType::circle);
  CHECK(scene.shape.points == 250);
  CHECK(scene.shape.spacing == 0.0);  // a point count, not a spacing: the format takes one of them
  CHECK(scene.grid_spacing == 0.03);
  CHECK(scene.h() == 0.03);
  CHECK(scene.radius_factor == 3.0);
  CHECK(scene.variant == Variant::exact);
  CHECK(scene.kind == MlsKind::affine);
  REQUIRE(scene.history.stages.size() == 1);
  CHECK(scene.history.stages[0].start == Handles{{1, 0}});
  CHECK(scene.history.total_steps() == 1);
  CHECK(scene.description.find("`amls deform` replays it") != std::string::npos);
}

TEST_CASE("a shape sampled at h keeps the h it was loaded with when the session changes the grid first") {
  SceneShape<2> ellipse;  // sampled at the grid's spacing, like a torus or a rounded box
  ellipse.type = ShapeType::ellipse;
  ellipse.semi_axes = Vec<2>(1.0, 0.5);
  SurfaceSettings s;
  s.spacing = 0.04;
  SessionRecording<2> r(ellipse, s);
  editor_step(r, {{1, 0}}, {{1.2, 0}}, s, true);
  CHECK(recorded_scene(r, "/tmp/x.json", "x").shape.spacing == 0.0);  // the same h: the shape as it was

  SessionRecording<2> regridded(ellipse, s);
  s.spacing = 0.02;  // set_grid before the first step
  editor_step(regridded, {{1, 0}}, {{1.2, 0}}, s, true);
  const Scene<2> scene = recorded_scene(regridded, "/tmp/x.json", "x");
  CHECK(scene.h() == 0.02);
  CHECK(scene.sample_spacing() == 0.04);
  CHECK(regridded.restarted(s).sampled_at() == 0.04);  // and after a reset
}
