#include <doctest/doctest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/run/scene.hpp"
#include "region_fixtures.hpp"
#include "tests/scene_errors.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// A 2D scene with two regions: the first pinned in stage 0 and moved in stage 1,
// the second moved (turned, scaled) in stage 0 beside a point handle.
const char* kRegions2d = R"({
  "dimension": 2,
  "shape": {"type": "circle", "radius": 1, "points": 200},
  "grid": {"spacing": 0.03},
  "regions": [
    {"points": [[1, 0], [0.99, 0.14], [0.99, -0.14]]},
    {"points": [[-1, 0], [-0.99, 0.14]], "reach": 0.05}
  ],
  "stages": [
    {"handles": [[0, 1]],
     "regions": [{"region": 0, "pinned": true}, {"region": 1}],
     "targets": [{"steps": 3, "handles": [[0, 1.1]],
                  "regions": [{}, {"translation": [-0.2, 0], "rotation": 0.5, "scale": 1.1}]}]},
    {"handles": [],
     "regions": [{"region": 0, "motion": {"translation": [0.01, 0]}}],
     "targets": [{"steps": 2, "handles": [], "regions": [{"translation": [0.2, 0]}]}]}
  ]
})";

std::string edited(const std::string& from, const std::string& to) {
  return amls::test::edited_text(kRegions2d, from, to);
}

bool mentions(const std::string& message, const std::string& part) {
  const bool found = message.find(part) != std::string::npos;
  if (!found) MESSAGE(message);
  return found;
}

}  // namespace

TEST_CASE("scene regions: read with their members, reach, pins and motions, and written back to the same scene") {
  TempDir dir;
  write_text(dir.file("scene.json"), kRegions2d);
  const Scene<2> s = std::get<Scene<2>>(read_scene(dir.file("scene.json")));
  REQUIRE(s.history.stages.size() == 2);
  const HandleStage<2>& first = s.history.stages[0];
  REQUIRE(first.regions.size() == 2);
  CHECK(first.regions[0].pinned);
  CHECK_FALSE(first.regions[1].pinned);
  CHECK(first.regions[0].region->members().size() == 3);
  CHECK(first.regions[0].region->reach() == 0.03);  // h, when not given
  CHECK(first.regions[1].region->reach() == 0.05);
  CHECK(first.targets[0].regions[1].rotation[0] == 0.5);
  CHECK(first.targets[0].regions[1].scale == 1.1);
  // The second stage takes up the first region again: the same members, shared.
  CHECK(s.history.stages[1].regions[0].region == first.regions[0].region);
  CHECK(s.history.stages[1].start.empty());
  CHECK(s.history.total_steps() == 5);
  const HistoryStep<2> step = s.history.step(1);
  CHECK(step.regions_from[1].motion.rotation[0] == doctest::Approx(0.5 / 3.0));
  CHECK(step.regions_to[1].motion.rotation[0] == doctest::Approx(1.0 / 3.0));

  write_scene(dir.file("again.json"), s);
  const Scene<2> again = std::get<Scene<2>>(read_scene(dir.file("again.json")));
  CHECK(to_json(again) == to_json(s));
  const nlohmann::json j = to_json(s);
  CHECK(j["regions"].size() == 2);
  CHECK(j["stages"][1]["regions"][0]["region"] == 0);
}

TEST_CASE("scene regions: the 3D fixture survives the round trip bit for bit") {
  RegionMotion<3> turned;
  turned.rotation = Vec<3>(0.1, 0.2, 0.3);
  turned.translation = Vec<3>(1.0 / 3.0, 0, 0);
  const Scene<3> scene = test::sphere_with_caps(0.1, turned, 4);
  const Scene<3> again = std::get<Scene<3>>(scene_from_json(to_json(scene), "in memory"));
  const HandleStage<3>& stage = again.history.stages[0];
  REQUIRE(stage.regions.size() == 2);
  CHECK(stage.regions[0].region->members() == scene.history.stages[0].regions[0].region->members());
  CHECK(stage.targets[0].regions[1] == turned);
}

TEST_CASE("scene regions: bad keys and values are refused with their place") {
  TempDir dir;
  struct Case {
    const char* from;
    const char* to;
    const char* message;
  };
  const Case cases[] = {
      {"{\"region\": 1}", "{\"region\": 2}", "stages[0].regions[1].region: must be within [0, 1] (a region's index), got 2"},
      {"{\"region\": 1}", "{\"region\": 0}", "stages[0].regions[1].region: region 0 is in this stage twice"},
      {"\"regions\": [{}, {\"translation\"", "\"regions\": [{\"scale\": 2}, {\"translation\"",
       "stages[0].targets[0].regions[0]: the region is pinned in this stage, but the target moves it"},
      {"\"regions\": [{}, {\"translation\"", "\"regions\": [{\"translation\"",
       "stages[0].targets[0].regions: 1 motions, but the stage has 2 regions"},
      {"\"scale\": 1.1", "\"scale\": 0", "stages[0].targets[0].regions[1].scale: must be within [0.001, 1000]"},
      {"\"rotation\": 0.5", "\"rotation\": [0.5]",
       "stages[0].targets[0].regions[1].rotation: expected a number, got an array"},
      {"\"reach\": 0.05", "\"reach\": -1", "regions[1].reach: must be within"},
      {"\"reach\": 0.05", "\"radius\": 1", "regions[1].radius: unknown key"},
      {"{\"points\": [[-1, 0], [-0.99, 0.14]], \"reach\": 0.05}", "{\"points\": []}",
       "regions[1].points: must be within [1, 2e+07]"},
      {"{\"translation\": [0.01, 0]}", "{\"translation\": [0.01, 0, 0]}",
       "stages[1].regions[0].motion.translation: expected an array of 2 numbers"},
      {"{\"translation\": [0.01, 0]}", "{\"shift\": [0.01, 0]}", "stages[1].regions[0].motion.shift: unknown key"},
      // A stage of regions alone may have no point handle; a stage with neither is refused.
      {"\"regions\": [{\"region\": 0, \"motion\"", "\"pins\": [{\"region\": 0, \"motion\"",
       "stages[1].handles: must be within [1, 1024] (handles in a stage), got 0"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.to);
    CHECK(mentions(amls::test::scene_error_of(edited(c.from, c.to), dir), c.message));
  }
  std::string no_regions = kRegions2d;
  const std::string cut = R"("regions": [
    {"points": [[1, 0], [0.99, 0.14], [0.99, -0.14]]},
    {"points": [[-1, 0], [-0.99, 0.14]], "reach": 0.05}
  ],)";
  no_regions.replace(no_regions.find(cut), cut.size(), "");
  CHECK(mentions(amls::test::scene_error_of(no_regions, dir),
                 "stages[0].regions[0]: the scene defines no 'regions' to refer to"));
}
