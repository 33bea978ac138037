#include <doctest/doctest.h>

#include <cmath>

#include "app/editor/edit_session.hpp"
#include "app/editor/initial_shape.hpp"
#include "app/editor/scene_start.hpp"
#include "editor_test_support.hpp"
#include "region_fixtures.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

const WorkControl kRunAll{};

// The session's current points with |z| > 0.7 on the side of `sign`: a polar cap, as a lasso would take it.
std::vector<Vec<3>> cap_of(const EditSession<3>& session, double sign) {
  std::vector<Vec<3>> out;
  for (const Vec<3>& p : session.points().positions)
    if (sign * p.z() > 0.7) out.push_back(p);
  return out;
}

// A sphere of 2,000 points at h = 0.08, its south cap pinned and its north cap a moving region.
EditSession<3> sphere_with_caps() {
  EditSession<3> session(make_sphere(1.0, 2000, 0.08), 1);
  session.add_region(cap_of(session, -1.0), 0.08, true);
  session.add_region(cap_of(session, 1.0), 0.08, false);
  return session;
}

// Moves the north cap through `motions`, one step each.
void drag_north(EditSession<3>& session, const std::vector<RegionMotion<3>>& motions) {
  session.begin_drag();
  for (const RegionMotion<3>& m : motions)
    REQUIRE(session.move_handles(session.handles(), {RegionMotion<3>{}, m}, kRunAll).stepped);
}

RegionMotion<3> lifted_and_turned(double k) {
  RegionMotion<3> m;
  m.translation = Vec<3>(0.05 * k, 0.0, 0.1 * k);
  m.rotation = Vec<3>(0.2 * k, 0.0, 0.0);
  return m;
}

}  // namespace

TEST_CASE("region session: regions are undoable, a pinned region refuses to move, a bad region is refused") {
  EditSession<3> session = sphere_with_caps();
  CHECK(session.regions().size() == 2);
  CHECK(session.regions()[0].pinned);
  CHECK_THROWS_AS(session.move_handles({}, {lifted_and_turned(1), RegionMotion<3>{}}, kRunAll), std::invalid_argument);
  CHECK_THROWS_AS(session.move_handles({}, {RegionMotion<3>{}}, kRunAll), std::invalid_argument);
  CHECK_THROWS_AS(session.add_region({}, 0.08, false), std::invalid_argument);
  CHECK_THROWS_AS(session.remove_region(2), std::out_of_range);
  session.remove_region(0);
  CHECK(session.regions().size() == 1);
  session.undo();
  REQUIRE(session.regions().size() == 2);
  CHECK(session.regions()[0].pinned);
  session.set_region_pinned(0, false);
  session.undo();
  CHECK(session.regions()[0].pinned);
}

TEST_CASE("region session: the dragged cap follows its motion, the pinned one stays, and undo restores both") {
  EditSession<3> session = sphere_with_caps();
  const PointSet<3> before = session.points();
  drag_north(session, {lifted_and_turned(1), lifted_and_turned(2), lifted_and_turned(3)});
  const RegionHandle<3>& north = session.regions()[1];
  CHECK(north.motion == lifted_and_turned(3));
  // Every point within reach of the moved north cap lies on the unit sphere moved as the cap was, and every
  // point within reach of the south cap on the unit sphere: within 0.05 h (h = 0.08) more than 3 h inside
  // their rims (z = 0.7 at rest), where no point's MLS support reaches the bent surface outside.
  const double h = 0.08, inner_z = std::cos(std::acos(0.7) - 3.0 * h);
  const PointRegion<3> moved(north.placed_members(), h);
  const PointRegion<3>& south = *session.regions()[0].region;
  const Mat<3> linear = north.motion.linear();
  const Vec<3> offset = north.motion.offset(north.region->centre());
  std::size_t in_north = 0, in_south = 0;
  double north_inside = 0.0, north_all = 0.0, south_inside = 0.0, south_all = 0.0;
  for (const Vec<3>& p : session.points().positions) {
    if (moved.contains(p)) {
      ++in_north;
      const Vec<3> rest = linear.transpose() * (p - offset);
      const double off = std::abs(rest.norm() - 1.0) / h;
      north_all = std::max(north_all, off);
      if (rest.normalized().z() > inner_z) north_inside = std::max(north_inside, off);
    }
    if (south.contains(p)) {
      ++in_south;
      const double off = std::abs(p.norm() - 1.0) / h;
      south_all = std::max(south_all, off);
      if (-p.normalized().z() > inner_z) south_inside = std::max(south_inside, off);
    }
  }
  CHECK(in_north > 100);
  CHECK(in_south > 100);
  CHECK(north_inside < 0.05);
  CHECK(south_inside < 0.05);
  // Near the rims, within the fits' reach of the blended surface.
  CHECK(north_all < 0.1);
  CHECK(south_all < 0.1);
  session.undo();
  CHECK(session.points().positions == before.positions);
  CHECK(session.regions()[1].motion.is_identity());
}

TEST_CASE("region session: a session with regions and point handles replays exactly as amls deform runs it") {
  for (const ResamplePolicy::Kind kind : {ResamplePolicy::Kind::always, ResamplePolicy::Kind::local}) {
    CAPTURE(static_cast<int>(kind));
    EditSession<3> session = sphere_with_caps();
    ResamplePolicy policy;
    policy.kind = kind;
    session.set_resampling(true, policy);
    drag_north(session, {lifted_and_turned(1), lifted_and_turned(2)});
    session.add_handle(Vec<3>(1.0, 0.0, 0.0));  // a new stage: a point handle beside the regions
    session.begin_drag();
    session.move_handles({Vec<3>(1.2, 0.0, 0.0)}, {RegionMotion<3>{}, lifted_and_turned(2)}, kRunAll);
    session.set_region_pinned(1, true);  // another stage: the north cap pinned where it is
    session.move_handles({Vec<3>(1.3, 0.1, 0.0)}, kRunAll);
    drag_north(session, {});
    session.undo();
    REQUIRE(session.recording().exact());
    CHECK(session.recording().history().stages.size() == 3);
    const PointSet<3> replayed = amls::test::replay_with_amls_deform(session.recording());
    CHECK(replayed.positions == session.points().positions);
    CHECK(replayed.normals == session.points().normals);
  }
}

TEST_CASE("region session: a scene's regions start the session, and its saved scene replays with them") {
  // The scene's north cap starts lifted and turned: the session takes its start motion as it is.
  Scene<3> scene = test::sphere_with_caps(0.08, lifted_and_turned(2), 1);
  scene.history.stages[0].regions[1].motion = lifted_and_turned(1);
  const InitialShape shape = start_from_scene(scene, 1);
  EditSession<3> session(shape, 1);
  // The same regions: members, reach, motions and pins.
  CHECK(session.regions() == scene.history.stages[0].regions);
  drag_north(session, {lifted_and_turned(2), lifted_and_turned(3)});
  REQUIRE(session.recording().exact());
  const DeformationHistory<3> saved = session.recording().history();
  REQUIRE(saved.stages.size() == 1);
  CHECK(saved.stages[0].regions == scene.history.stages[0].regions);
  const PointSet<3> replayed = amls::test::replay_with_amls_deform(session.recording());
  CHECK(replayed.positions == session.points().positions);
  CHECK(replayed.normals == session.points().normals);
  // Reset goes back to the scene's regions where the scene put them.
  session.reset();
  CHECK(session.regions() == scene.history.stages[0].regions);
}

TEST_CASE("region session: start regions of another dimension are refused") {
  InitialShape shape = make_sphere(1.0, 500, 0.2);
  const auto flat = std::make_shared<const PointRegion<2>>(std::vector<Vec<2>>{Vec<2>(1.0, 0.0)}, 0.2);
  shape.regions = std::vector<RegionHandle<2>>{{flat, {}, false}};
  CHECK_THROWS_AS(EditSession<3>(shape, 1), std::invalid_argument);
}
