// Region handles on a real scan: CGAL's kitten (real_data_files.hpp). Its feet are pinned and its head moved as one piece in 40
// steps, as a user would select and drag them in the editor.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/scene_run.hpp"
#include "real_data_files.hpp"
#include "surface_fixtures.hpp"
#include "temp_dir.hpp"

using namespace amls;
using amls::test::data_file;

namespace {

nlohmann::json points_json(const std::vector<Vec<3>>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const Vec<3>& p : points) out.push_back({p.x(), p.y(), p.z()});
  return out;
}

// How far x lies from the surface: |F| / |grad F|, the distance to the fitted sphere to first order.
double off_surface(const AmlsSurface<3>& surface, const Vec<3>& x) {
  const Evaluation<3> e = surface.evaluate(x);
  REQUIRE(e.defined);
  return std::abs(e.value) / e.gradient.norm();
}

struct Kept {
  std::size_t points = 0;  // final points within the region's reach
  double worst_h = 0.0;    // the farthest of them, moved back, from the file's surface
};

}  // namespace

TEST_CASE("real data, regions: the kitten's pinned feet stay and its moved head follows over a 40-step drag") {
  const LoadedPointSet scan = read_point_set(data_file("points_3/kitten.xyz"));
  REQUIRE(scan.points.size() == 5210);
  // The kitten as a session holds it: resampled at its h, twice. The first resample of a raw scan moves its
  // MLS surface by up to 0.13 h (the scan's noise smoothed away), which would hide what the regions do.
  PointSetResampling resampling;
  resampling.threads = 2;
  const ResampledPointSet<3> once = resample_point_set(scan.points, resampling);
  resampling.spacing = once.grid.spacing();
  const PointSet<3> kitten = resample_point_set(once.points, resampling).points;
  test::TempDir folder;
  const std::string path = folder.file("kitten.ply");
  write_point_set(path, kitten, PointFileFormat::ply_binary_little_endian, resampling.spacing);
  // The kitten stands along y, about a unit tall: its feet below y = -0.35, its head above y = 0.3.
  std::vector<Vec<3>> feet, head, others;
  for (const Vec<3>& p : kitten.positions)
    (p.y() < -0.35 ? feet : p.y() > 0.3 ? head : others).push_back(p);
  RegionMotion<3> moved;
  moved.translation = Vec<3>(0.08, 0.06, -0.04);
  moved.rotation = Vec<3>(0.0, 0.0, 0.25);
  const nlohmann::json motion = {{"translation", {0.08, 0.06, -0.04}}, {"rotation", {0.0, 0.0, 0.25}}};
  const nlohmann::json json = {
      {"dimension", 3},
      {"shape", {{"type", "file"}, {"path", path}}},
      {"grid", {{"spacing", resampling.spacing}}},
      {"regions", {{{"points", points_json(feet)}}, {{"points", points_json(head)}}}},
      {"stages",
       {{{"handles", nlohmann::json::array()},
         {"regions", {{{"region", 0}, {"pinned", true}}, {{"region", 1}}}},
         {"targets", {{{"steps", 40}, {"handles", nlohmann::json::array()}, {"regions", {nlohmann::json::object(), motion}}}}}}}}};
  const Scene<3> scene = std::get<Scene<3>>(scene_from_json(json, path + ".json"));
  const std::vector<RegionHandle<3>> regions = scene.history.stages.at(0).regions;
  REQUIRE(regions.size() == 2);
  REQUIRE(regions[1].region->members().size() > 300);
  REQUIRE(regions[0].region->members().size() > 300);

  // The resamples keep the points that the regions hold as their motions put them (the feet where they
  // are, the head moved rigidly), so every point within a region's reach, up to its rim, lies on the
  // file's surface moved with the region. Resampled instead, the points within 3 h of a region's rim were
  // fitted to the blended surface outside too, and a scan's surface creeps under repeated resampling by
  // itself (0.7 h in 40 steps with nothing moved, under `always`).
  ThreadPool pool(2);
  const AmlsSurface<3> reference =
      test::ready_surface(kitten, resampling_grid(kitten, scene.h(), scene.radius_factor), pool, scene.parameters());
  for (const ResamplePolicy::Kind policy : {ResamplePolicy::Kind::always, ResamplePolicy::Kind::local}) {
    CAPTURE(static_cast<int>(policy));
    SceneRunOptions options;
    options.tracers_per_point = 1;
    options.policy.kind = policy;
    options.threads = 2;
    PointSet<3> after;
    const SceneRunReport report =
        run_scene<3>(scene, options, [&](std::size_t, const PointSet<3>& p) { after = p; });
    REQUIRE_FALSE(report.broken);
    REQUIRE(report.steps == 40);
    CHECK(report.final_holes == 0);  // the surface between the regions stays closed
    const double h = report.h;
    const auto kept = [&](const RegionHandle<3>& handle) {
      Kept out;
      const PointRegion<3> region(handle.placed_members(), handle.region->reach());
      const Mat<3> back = handle.motion.linear().inverse();
      const Vec<3> offset = handle.motion.offset(handle.region->centre());
      for (const Vec<3>& x : after.positions) {
        if (!region.contains(x)) continue;
        ++out.points;
        out.worst_h = std::max(out.worst_h, off_surface(reference, back * (x - offset)) / h);
      }
      return out;
    };
    const Kept feet_kept = kept(regions[0]);
    const Kept head_kept = kept(RegionHandle<3>{regions[1].region, moved, false});
    MESSAGE("h = " << h << ": feet " << feet_kept.points << " points, " << feet_kept.worst_h << " h off; head "
                   << head_kept.points << " points, " << head_kept.worst_h << " h off");
    CHECK(feet_kept.points > 100);
    CHECK(head_kept.points > 100);
    CHECK(feet_kept.worst_h < 0.05);
    CHECK(head_kept.worst_h < 0.05);
  }
}
