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
  std::size_t points = 0;  // final points within the region's reach, their fits more than 3 h from its rim
  double worst_h = 0.0;    // the farthest of them, moved back, from the surface of the run without the drag
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

  // Resampling a scan over and over moves its surface by itself (the MLS surface of the resampled points is
  // not the scan's exactly: on the kitten under `always`, 0.7 h in 40 steps with nothing moved). What the
  // regions must keep is measured against the same run with the head left where it is: against the surface
  // its last points were sampled from - under `always` that of the points before its last step, under
  // `local` (which resamples only where a step strained the points, and nothing moves there) the file's own.
  Scene<3> still = scene;
  still.history.stages[0].targets[0].regions[1] = RegionMotion<3>{};

  for (const ResamplePolicy::Kind policy : {ResamplePolicy::Kind::always, ResamplePolicy::Kind::local}) {
    CAPTURE(static_cast<int>(policy));
    SceneRunOptions options;
    options.tracers_per_point = 1;
    options.policy.kind = policy;
    options.threads = 2;
    PointSet<3> after, sampled_from;
    const SceneRunReport report =
        run_scene<3>(scene, options, [&](std::size_t, const PointSet<3>& p) { after = p; });
    run_scene<3>(still, options, [&](std::size_t step, const PointSet<3>& p) {
      if (step + 1 == report.steps) sampled_from = p;
    });
    if (policy == ResamplePolicy::Kind::local) sampled_from = kitten;
    REQUIRE_FALSE(report.broken);
    REQUIRE(report.steps == 40);
    CHECK(report.final_holes == 0);  // the surface between the regions stays closed
    const double h = report.h;
    ThreadPool pool(2);
    const AmlsSurface<3> reference = test::ready_surface(
        sampled_from, resampling_grid(sampled_from, h, scene.radius_factor), pool, scene.parameters());
    // Within 3 h (the MLS support) of a region's rim the fits see the blended surface outside too: the
    // region's own points are those whose nearest point outside it is farther. Under `local`, farther
    // still by one lattice cell (8 h): the strain of the bent neck is its lattice cell's, and every point of
    // the cell is resampled, one resample more than the unmoved run had there (on the kitten that alone moves
    // points by up to 0.08 h, 4 to 8 h into the head; nothing within reach of the feet moves at all).
    const double rim = policy == ResamplePolicy::Kind::local ? 11.0 * h : 3.0 * h;
    const PointRegion<3> outside(others, h);
    const auto kept = [&](const RegionHandle<3>& handle) {
      Kept out;
      const PointRegion<3> region(handle.placed_members(), handle.region->reach());
      const Mat<3> back = handle.motion.linear().inverse();
      const Vec<3> offset = handle.motion.offset(handle.region->centre());
      for (const Vec<3>& x : after.positions) {
        if (!region.contains(x)) continue;
        const Vec<3> rest = back * (x - offset);
        if (outside.squared_distance(rest) < rim * rim) continue;
        ++out.points;
        out.worst_h = std::max(out.worst_h, off_surface(reference, rest) / h);
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
