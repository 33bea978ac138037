#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include "app/editor/session_recording.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

using Handles = std::vector<Vec<2>>;

ShapeSource circle_source() {
  ShapeSource s;
  s.type = ShapeSource::Type::circle;
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

TEST_CASE("steps that continue each other share a stage; a changed handle set starts one") {
  SessionRecording<2> r(circle_source(), {});
  const SurfaceSettings s;
  const Handles a{{1, 0}}, b{{1.1, 0}}, c{{1.2, 0}};
  const Handles c2{{1.2, 0}, {0, 1}}, d2{{1.2, 0}, {0, 1.2}};
  editor_step(r, a, b, s, true);
  editor_step(r, b, c, s, false);
  editor_step(r, c2, d2, s, false);  // a handle was added
  const auto stages = r.stages();
  REQUIRE(stages.size() == 2);
  CHECK(stages[0].start == a);
  CHECK(stages[0].targets == std::vector<Handles>{b, c});
  CHECK(stages[1].start == c2);
  CHECK(stages[1].targets == std::vector<Handles>{d2});
  CHECK(r.exact());
}

TEST_CASE("settings changed before the first step are the scene's; after it they spoil an exact replay") {
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

TEST_CASE("a session without resampling is replayed with --no-resample; switching it on spoils that") {
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

TEST_CASE("a change of MLS kind or alpha after the first step spoils an exact replay") {
  SurfaceSettings s;
  SessionRecording<2> r(circle_source(), s);
  editor_step(r, {{1, 0}}, {{1.1, 0}}, s, true);
  s.alpha = 2.0;
  editor_step(r, {{1.1, 0}}, {{1.2, 0}}, s, false);
  CHECK(!r.exact());
}

TEST_CASE("the scene JSON has the scene format's keys, one step per target, and says how to replay it") {
  SurfaceSettings s;
  s.spacing = 0.03;
  SessionRecording<2> r(circle_source(), s);
  CHECK_THROWS_AS(scene_json(r, "/tmp/x.json", "x"), std::runtime_error);
  editor_step(r, {{1, 0}}, {{1.1, 0.5}}, s, true);
  const nlohmann::ordered_json j = scene_json(r, "/tmp/x.json", "session");
  CHECK(j["dimension"] == 2);
  CHECK(j["name"] == "session");
  CHECK(j["shape"]["type"] == "circle");
  CHECK(j["shape"]["points"] == 250);
  CHECK(j["shape"]["center"] == nlohmann::ordered_json::array({0.0, 0.0}));
  CHECK(j["grid"]["spacing"] == 0.03);
  CHECK(j["radius_factor"] == 3.0);
  CHECK(j["variant"] == "exact");
  CHECK(j["deformation"]["kind"] == "rigid");
  CHECK(j["stages"].size() == 1);
  CHECK(j["stages"][0]["handles"] == nlohmann::ordered_json::parse("[[1.0, 0.0]]"));
  CHECK(j["stages"][0]["targets"][0]["steps"] == 1);
  CHECK(j["stages"][0]["targets"][0]["handles"] == nlohmann::ordered_json::parse("[[1.1, 0.5]]"));
  CHECK(j["description"].get<std::string>().find("`amls deform` replays it") != std::string::npos);
  // Every double survives the text round trip bit for bit.
  const auto back = nlohmann::json::parse(j.dump());
  CHECK(back["stages"][0]["targets"][0]["handles"][0][0].get<double>() == 1.1);
}

TEST_CASE("a file shape is named relative to the scene's folder") {
  ShapeSource file;
  file.type = ShapeSource::Type::file;
  file.path = "/data/shapes/bunny.ply";
  SessionRecording<3> r(file, {});
  r.deformed({Vec<3>(0, 0, 1)}, {Vec<3>(0, 0, 2)}, {});
  CHECK(scene_json(r, "/data/scenes/s.json", "s")["shape"]["path"] == "../shapes/bunny.ply");
  CHECK(scene_json(r, "/data/shapes/s.json", "s")["shape"]["path"] == "bunny.ply");
}
