#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>

#include "app/editor/edit_session.hpp"
#include "app/editor/initial_shape.hpp"
#include "app/editor/scene_start.hpp"
#include "core/geometry/coverage.hpp"
#include "core/io/point_set_io.hpp"
#include "core/resample/resample_policy.hpp"
#include "editor_test_support.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

const WorkControl kRunAll{};

std::pair<double, double> x_range(const PointSet<2>& points) {
  double lo = 1e300, hi = -1e300;
  for (const Vec<2>& p : points.positions) {
    lo = std::min(lo, p.x());
    hi = std::max(hi, p.x());
  }
  return {lo, hi};
}

// The unit circle with handles on its left and right ends.
EditSession<2> circle_with_two_handles(int threads = 1) {
  EditSession<2> session(make_circle(1.0, 250, 0.024), threads);
  session.add_handle(Vec<2>(-1.0, 0.0));
  session.add_handle(Vec<2>(1.0, 0.0));
  return session;
}

// Positions in lexicographic order: the point set without its order.
std::vector<Vec<2>> sorted(std::vector<Vec<2>> v) {
  std::sort(v.begin(), v.end(), [](const Vec<2>& a, const Vec<2>& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  return v;
}

// Drags the right handle to x in `moves` steps.
void drag_right_handle(EditSession<2>& session, double x, int moves) {
  session.begin_drag();
  const double x0 = session.handles()[1].x();
  for (int k = 1; k <= moves; ++k) {
    std::vector<Vec<2>> to = session.handles();
    to[1].x() = x0 + (x - x0) * k / moves;
    REQUIRE(session.move_handles(to, kRunAll).stepped);
  }
}

// Runs the step to `to` with a control that says stop from its k-th poll on,
// for k = 1, 2, ... until the step gets through: so it is stopped before each
// phase and at every poll inside one. Calls after_stop() after each stopped
// try and counts them in `stops`; returns the step that got through.
template <typename AfterStop>
EditResult stop_at_every_poll(EditSession<2>& session, const std::vector<Vec<2>>& to, int& stops,
                              AfterStop&& after_stop) {
  std::atomic<int> polls{0};
  int stop_at = 0;
  const WorkControl control{[&] { return ++polls >= stop_at; }, {}};
  for (stop_at = 1;; ++stop_at) {
    polls = 0;
    const EditResult result = session.move_handles(to, control);
    if (!result.cancelled) return result;
    ++stops;
    after_stop(result);
  }
}

}  // namespace

TEST_CASE("dragging one handle of two stretches the circle towards it and keeps the other end") {
  EditSession<2> session = circle_with_two_handles();
  drag_right_handle(session, 1.5, 5);
  const auto [lo, hi] = x_range(session.points());
  CHECK(hi == doctest::Approx(1.5).epsilon(0.01));
  CHECK(lo == doctest::Approx(-1.0).epsilon(0.01));
  // The resampled curve stays sampled at about h.
  CHECK(session.points().size() > 250);
}

TEST_CASE("undo restores the point set and handles of the drag's start exactly - redo its end") {
  EditSession<2> session = circle_with_two_handles();
  drag_right_handle(session, 1.3, 3);
  const PointSet<2> before = session.points();
  const auto handles_before = session.handles();
  drag_right_handle(session, 1.6, 3);
  const PointSet<2> after = session.points();
  REQUIRE(session.undo());
  CHECK(session.points().positions == before.positions);
  CHECK(session.points().normals == before.normals);
  CHECK(session.handles() == handles_before);
  REQUIRE(session.redo());
  CHECK(session.points().positions == after.positions);
  CHECK(session.handles()[1].x() == 1.6);
}

TEST_CASE("Esc (cancel_drag) returns to the drag's start and leaves nothing to redo") {
  EditSession<2> session = circle_with_two_handles();
  const PointSet<2> start = session.points();
  drag_right_handle(session, 1.4, 2);
  REQUIRE(session.cancel_drag());
  CHECK(session.points().positions == start.positions);
  CHECK(session.handles()[1].x() == 1.0);
  CHECK(!session.can_redo());
  CHECK(session.recording().steps().empty());
}

TEST_CASE("a step stopped between its phases leaves the session as before it") {
  EditSession<2> session = circle_with_two_handles();
  const PointSet<2> start = session.points();
  for (int stop_after : {-1, 0, 1}) {  // before the first, second and third phase
    int phases = 0;
    const WorkControl control{[&] { return phases > stop_after; }, [&](const char*, int, int) { ++phases; }};
    std::vector<Vec<2>> to = session.handles();
    to[1].x() = 1.3;
    const EditResult result = session.move_handles(to, control);
    CHECK(result.cancelled);
    CHECK(!result.changed);
    CHECK(session.points().positions == start.positions);
    CHECK(session.handles()[1].x() == 1.0);
    CHECK(session.recording().steps().empty());
  }
  // And the next step runs as if nothing had happened.
  std::vector<Vec<2>> to = session.handles();
  to[1].x() = 1.3;
  CHECK(session.move_handles(to, kRunAll).stepped);
}

TEST_CASE("a step stopped anywhere inside its phases leaves the session as before it, and runs the same after") {
  for (int threads : {1, 2}) {
    CAPTURE(threads);
    EditSession<2> reference = circle_with_two_handles(threads);
    std::vector<Vec<2>> to = reference.handles();
    to[1].x() = 1.3;
    REQUIRE(reference.move_handles(to, kRunAll).stepped);  // no check: each pool block runs whole

    EditSession<2> session = circle_with_two_handles(threads);
    const PointSet<2> start = session.points();
    session.evaluable_surface();  // pseudo-normals of the start, as the 2D curve has them before a step
    int stops = 0;
    const EditResult result = stop_at_every_poll(session, to, stops, [&](const EditResult& stopped) {
      CHECK(!stopped.changed);
      CHECK(session.points().positions == start.positions);
      CHECK(session.points().normals == start.normals);
      CHECK(session.handles()[1].x() == 1.0);
      CHECK(session.recording().steps().empty());
      CHECK(session.evaluable_surface().evaluate(Vec<2>(1.0, 0.0)).defined);
    });
    // Only three polls come before a phase (resample, deform, resample): the other stops were inside one.
    CHECK(stops > 3);
    CHECK(result.stepped);
    CHECK(session.points().positions == reference.points().positions);
    CHECK(session.points().normals == reference.points().normals);
    CHECK(session.recording().steps().size() == reference.recording().steps().size());
  }
}

TEST_CASE("a variant change stopped inside its resample keeps the new variant and the points as they were") {
  EditSession<2> session(make_circle(1.0, 250, 0.024), 1);
  const PointSet<2> before = session.points();
  // The first poll comes before the resample, the second inside it.
  std::atomic<int> polls{0};
  const WorkControl stop_inside{[&] { return ++polls >= 2; }, {}};
  const EditResult result = session.set_variant(Variant::interpolated, stop_inside);
  CHECK(polls == 2);
  CHECK(result.cancelled);
  CHECK(result.changed);
  CHECK(!result.has_stats);
  CHECK(session.settings().variant == Variant::interpolated);
  CHECK(session.points().positions == before.positions);
  CHECK(session.points().normals == before.normals);
  // Stopped before its resample, a change keeps the surface and its pool, and
  // the check is off the pool again: work on it outside an edit (the
  // pseudo-normals, for the 2D curve) runs through.
  const WorkControl stop_at_once{[] { return true; }, {}};
  CHECK(session.set_variant(Variant::exact, stop_at_once).cancelled);
  CHECK(session.settings().variant == Variant::exact);
  CHECK(session.evaluable_surface().evaluate(Vec<2>(1.0, 0.0)).defined);
  CHECK(session.points().positions == before.positions);
  CHECK(session.set_variant(Variant::interpolated, kRunAll).has_stats);
  CHECK(session.points().positions != before.positions);
}

TEST_CASE("a step reports its phases: resample the loaded points, deform, resample") {
  EditSession<2> session = circle_with_two_handles();
  std::vector<std::string> names;
  const WorkControl control{{}, [&](const char* name, int, int) { names.push_back(name); }};
  std::vector<Vec<2>> to = session.handles();
  to[1].x() = 1.1;
  session.move_handles(to, control);
  CHECK(names == std::vector<std::string>{"resampling", "deforming", "resampling"});
  names.clear();
  to[1].x() = 1.2;
  session.move_handles(to, control);
  CHECK(names == std::vector<std::string>{"deforming", "resampling"});
}

TEST_CASE("toggling the variant resamples the surface at once, without deforming it") {
  EditSession<2> session(make_circle(1.0, 250, 0.024), 1);
  const PointSet<2> exact_points = session.points();
  const EditResult result = session.set_variant(Variant::interpolated, kRunAll);
  CHECK(result.changed);
  CHECK(result.has_stats);
  CHECK(session.points().positions != exact_points.positions);
  for (const Vec<2>& p : session.points().positions) CHECK(std::abs(p.norm() - 1.0) < 0.01);
  CHECK(session.can_undo());
  session.undo();
  CHECK(session.settings().variant == Variant::exact);
  CHECK(session.points().positions == exact_points.positions);
}

TEST_CASE("without resampling a step only deforms, so the points spread apart") {
  EditSession<2> session = circle_with_two_handles();
  session.set_resampling(false, ResamplePolicy{});
  const std::size_t n = session.points().size();
  drag_right_handle(session, 2.0, 2);
  CHECK(session.points().size() == n);
  CHECK(x_range(session.points()).second == doctest::Approx(2.0).epsilon(0.01));
}

TEST_CASE("the undo history is capped by bytes: the newest states that fit, and always the newest one") {
  const InitialShape shape = make_circle(1.0, 250, 0.024);
  // One state of this circle: its 250 points with normals, about 8 kB.
  const std::size_t state = 250 * 2 * sizeof(Vec<2>);
  auto undos = [](EditSession<2>& session) {
    int n = 0;
    while (session.undo()) ++n;
    return n;
  };
  {
    EditSession<2> session(shape, 1, 3 * state + state / 2);  // room for three states
    for (int k = 0; k < 10; ++k) session.add_handle(Vec<2>(0.1 * k, 0.0));
    CHECK(undos(session) == 3);
    CHECK(session.handles().size() == 7);  // back three of the ten additions
    // Redo brings the three back; a redo's state counts against the same budget.
    int redos = 0;
    while (session.redo()) ++redos;
    CHECK(redos == 3);
    CHECK(session.handles().size() == 10);
    CHECK(undos(session) == 3);
  }
  {
    EditSession<2> session(shape, 1, 1);  // no room at all: the newest state is kept anyway
    session.add_handle(Vec<2>(0.0, 0.0));
    session.add_handle(Vec<2>(0.5, 0.0));
    CHECK(undos(session) == 1);
    CHECK(session.handles().size() == 1);
  }
  {
    EditSession<2> session(shape, 1);  // the default budget holds hundreds of such states
    for (int k = 0; k < 150; ++k) session.add_handle(Vec<2>(0.001 * k, 0.0));
    CHECK(undos(session) == 150);
  }
}

TEST_CASE("handles: removing and adding are undoable, a bad index is refused") {
  EditSession<2> session = circle_with_two_handles();
  CHECK_THROWS_AS(session.remove_handle(2), std::out_of_range);
  session.remove_handle(0);
  CHECK(session.handles().size() == 1);
  session.undo();
  CHECK(session.handles().size() == 2);
  std::vector<Vec<2>> wrong(3, Vec<2>::Zero());
  CHECK_THROWS_AS(session.move_handles(wrong, kRunAll), std::invalid_argument);
}

TEST_CASE("a grid change resamples at the new spacing - reset goes back to the initial shape") {
  EditSession<2> session = circle_with_two_handles();
  drag_right_handle(session, 1.3, 2);
  session.set_grid(0.012, 3.0, kRunAll);
  CHECK(session.settings().spacing == 0.012);
  CHECK(session.points().size() > 450);
  session.reset();
  CHECK(session.points().size() == 250);
  CHECK(session.handles().empty());
  CHECK(session.settings().spacing == 0.012);
  CHECK(session.recording().steps().empty());
  session.undo();
  CHECK(session.points().size() > 450);
}

TEST_CASE("a grid spacing that would make millions of points is refused and changes nothing") {
  EditSession<3> session(make_sphere(1.0, 2000, 0.08), 1);
  const PointSet<3> before = session.points();
  CHECK_THROWS_WITH_AS(session.set_grid(0.0001, 3.0, kRunAll), doctest::Contains("larger grid spacing"),
                       std::invalid_argument);
  CHECK(session.settings().spacing == 0.08);
  CHECK(session.points().positions == before.positions);
  CHECK(!session.can_undo());
}

TEST_CASE("a session of handle drags, handle changes, an undo and an Esc replays exactly as amls deform runs it") {
  EditSession<2> session = circle_with_two_handles();
  drag_right_handle(session, 1.3, 4);
  session.add_handle(Vec<2>(0.0, 1.0));  // a new stage
  session.begin_drag();
  std::vector<Vec<2>> to = session.handles();
  for (double y : {1.1, 1.25, 1.4}) {
    to[2].y() = y;
    session.move_handles(to, kRunAll);
  }
  drag_right_handle(session, 1.8, 2);
  session.undo();                      // drops the last drag
  drag_right_handle(session, 1.1, 3);  // and Esc drops this one
  session.cancel_drag();
  session.remove_handle(0);  // another stage
  drag_right_handle(session, 1.5, 2);

  const SessionRecording<2>& recording = session.recording();
  REQUIRE(recording.exact());
  CHECK(recording.steps().size() == 4 + 3 + 2);
  CHECK(recording.history().stages.size() == 3);
  const PointSet<2> replayed = amls::test::replay_with_amls_deform(recording);
  CHECK(replayed.positions == session.points().positions);
  CHECK(replayed.normals == session.points().normals);
}

TEST_CASE("under auto a session resamples only where the sampling asks, and replays exactly with --resample auto") {
  EditSession<2> session = circle_with_two_handles();
  CHECK_THROWS_AS(session.set_resampling(true, ResamplePolicy{ResamplePolicy::Kind::every, 0}), std::invalid_argument);
  session.set_resampling(true, ResamplePolicy::parse("auto"));
  std::vector<std::string> names;
  const WorkControl control{{}, [&](const char* name, int, int) { names.push_back(name); }};
  std::size_t resamples = 0, steps = 0;
  session.begin_drag();
  std::vector<Vec<2>> to = session.handles();
  for (int k = 1; k <= 20; ++k) {
    to[1].x() = 1.0 + 0.15 * k;  // 6 h a step: the circle stretches to 2.5 times its width
    const EditResult result = session.move_handles(to, control);
    REQUIRE(result.stepped);
    resamples += result.resamples;
    ++steps;
  }
  // The first step resamples the loaded points (step 0 always does); every
  // step is followed by a check, and by a resample only where it failed.
  CHECK(names.at(0) == "resampling");
  CHECK(std::count(names.begin(), names.end(), "checking the sampling") == 20);
  CHECK(std::count(names.begin(), names.end(), "resampling") == static_cast<std::ptrdiff_t>(resamples));
  CHECK(resamples >= 2);
  CHECK(resamples < steps);
  const SessionRecording<2>& recording = session.recording();
  REQUIRE(recording.exact());
  CHECK(recording.replay_arguments() == "--resample auto");
  const PointSet<2> replayed = amls::test::replay_with_amls_deform(recording);
  CHECK(replayed.positions == session.points().positions);
  CHECK(replayed.normals == session.points().normals);
}

TEST_CASE("under local a session resamples where strained, keeps the strain through undo, and replays exactly") {
  EditSession<2> session = circle_with_two_handles();
  session.set_resampling(true, ResamplePolicy::parse("local"));
  std::vector<std::string> names;
  const WorkControl control{{}, [&](const char* name, int, int) { names.push_back(name); }};
  std::size_t resamples = 0;
  session.begin_drag();
  std::vector<Vec<2>> to = session.handles();
  for (int k = 1; k <= 12; ++k) {
    to[1].x() = 1.0 + 0.15 * k;  // 6 h a step: the right half stretches, the left barely moves
    const EditResult result = session.move_handles(to, control);
    REQUIRE(result.stepped);
    resamples += result.resamples;
  }
  // The loaded points are resampled whole once; then each step is one phase.
  CHECK(names.at(0) == "resampling");
  CHECK(std::count(names.begin(), names.end(), "resampling") == 1);
  CHECK(std::count(names.begin(), names.end(), "deforming, resampling where strained") == 12);
  CHECK(resamples >= 2);  // the start, and steps that strained the sampling somewhere
  const SessionRecording<2>& recording = session.recording();
  REQUIRE(recording.exact());
  CHECK(recording.replay_arguments() == "--resample local");
  // The points as a set are the replay's (the session need not keep them in the replay's order).
  const PointSet<2> replayed = amls::test::replay_with_amls_deform(recording);
  CHECK(sorted(replayed.positions) == sorted(session.points().positions));
  // The surface to evaluate takes the local loop's points only when asked for, and then holds them all.
  const std::vector<Vec<2>> local_points = session.points().positions;
  CHECK(sorted(session.evaluable_surface().points().positions) == sorted(local_points));
  CHECK(session.points().positions == local_points);  // in the same order as before
  // An undo restores the points with their strain: the next step runs locally, without a whole resample.
  const PointSet<2> after = session.points();
  REQUIRE(session.undo());
  REQUIRE(session.redo());
  CHECK(sorted(session.points().positions) == sorted(after.positions));
  names.clear();
  to[1].x() += 0.15;
  REQUIRE(session.move_handles(to, control).stepped);
  CHECK(std::count(names.begin(), names.end(), "resampling") == 0);
}

TEST_CASE("under local a step stopped inside its phase leaves the session as before it, and runs the same after") {
  EditSession<2> reference = circle_with_two_handles(2), session = circle_with_two_handles(2);
  for (EditSession<2>* s : {&reference, &session}) s->set_resampling(true, ResamplePolicy::parse("local"));
  std::vector<Vec<2>> to = reference.handles();
  to[1].x() = 1.15;
  REQUIRE(reference.move_handles(to, kRunAll).stepped);
  REQUIRE(session.move_handles(to, kRunAll).stepped);
  to[1].x() = 1.3;
  REQUIRE(reference.move_handles(to, kRunAll).stepped);
  const PointSet<2> start = session.points();
  int stops = 0;
  const EditResult result = stop_at_every_poll(session, to, stops, [&](const EditResult&) {
    CHECK(session.points().positions == start.positions);
    CHECK(session.recording().steps().size() == 1);
  });
  CHECK(stops > 1);  // one poll comes before the phase: the others were inside it
  CHECK(result.stepped);
  CHECK(session.points().positions == reference.points().positions);
  CHECK(session.recording().exact());
}

TEST_CASE("a 3D session replays exactly too") {
  EditSession<3> session(make_sphere(1.0, 2000, 0.08), 1);
  session.add_handle(Vec<3>(0.0, 0.0, 1.0));
  session.add_handle(Vec<3>(0.0, 0.0, -1.0));
  session.set_deformation(MlsKind::similarity, 1.5);
  session.begin_drag();
  std::vector<Vec<3>> to = session.handles();
  for (double z : {1.1, 1.25}) {
    to[0].z() = z;
    session.move_handles(to, kRunAll);
  }
  REQUIRE(session.recording().exact());
  CHECK(session.recording().settings().kind == MlsKind::similarity);
  const PointSet<3> replayed = amls::test::replay_with_amls_deform(session.recording());
  CHECK(replayed.positions == session.points().positions);
}

TEST_CASE("a shape sampled at h replays exactly after the grid changed before the first step") {
  Scene<2> scene;  // an ellipse has no point count: it is sampled at the grid's spacing
  scene.shape.type = ShapeType::ellipse;
  scene.shape.semi_axes = Vec<2>(1.0, 0.6);
  scene.grid_spacing = 0.04;
  EditSession<2> session(start_from_scene(scene, 1), 1);
  session.set_grid(0.03, 3.0, kRunAll);
  session.add_handle(Vec<2>(-1.0, 0.0));
  session.add_handle(Vec<2>(1.0, 0.0));
  drag_right_handle(session, 1.3, 2);
  REQUIRE(session.recording().exact());
  const PointSet<2> replayed = amls::test::replay_with_amls_deform(session.recording());
  CHECK(replayed.positions == session.points().positions);
}

TEST_CASE("a point set sparse in places opens with widened supports: the session has no gap and replays exactly") {
  amls::test::TempDir dir;
  const std::string path = dir.file("half_sparse.ply");
  write_point_set(path, amls::test::half_sparse_sphere(3000), PointFileFormat::ply_binary_little_endian);
  InitialShape shape = load_initial_shape(path, 1);
  CHECK(shape.settings.widen_support);
  CHECK_FALSE(shape.coverage_loss);
  CHECK(shape.coverage.find("support widened at") != std::string::npos);

  // Two drag steps: the top pulled up, the bottom held. Each step's resample
  // closes the sparse half only with widened supports.
  auto drag_top = [](EditSession<3>& session) {
    session.add_handle(Vec<3>(0.0, 0.0, 1.0));
    session.add_handle(Vec<3>(0.0, 0.0, -1.0));
    session.begin_drag();
    std::vector<Vec<3>> to = session.handles();
    for (double z : {1.05, 1.1}) {
      to[0].z() = z;
      REQUIRE(session.move_handles(to, kRunAll).stepped);
    }
  };
  auto gap_fraction = [](EditSession<3>& session) {
    return static_cast<double>(unsurrounded_points(session.points(), session.settings().spacing, kGapReach,
                                                   session.pool())) /
           static_cast<double>(session.points().size());
  };
  EditSession<3> widened(shape, 1);
  drag_top(widened);
  CHECK(gap_fraction(widened) < 0.01);
  REQUIRE(widened.recording().exact());
  CHECK(recorded_scene(widened.recording(), dir.file("s.json"), "s").widen_support);
  const PointSet<3> replayed = amls::test::replay_with_amls_deform(widened.recording());
  CHECK(replayed.positions == widened.points().positions);
  CHECK(replayed.normals == widened.points().normals);

  shape.settings.widen_support = false;
  EditSession<3> uniform(shape, 1);
  drag_top(uniform);
  // Where the sparse half kept its place (the bottom handle held it), no
  // part of the sphere is more than 1.5 h from the session's points; with one
  // Delta most of it is.
  std::vector<Vec<3>> probes;
  for (const Vec<3>& p : sample_sphere(Vec<3>::Zero(), 1.0, 2000).positions)
    if (p.z() < -0.5) probes.push_back(p);
  const double reach = 1.5 * shape.settings.spacing;
  CHECK(amls::test::probes_in_holes(widened.points().positions, probes, reach) == 0);
  CHECK(amls::test::probes_in_holes(uniform.points().positions, probes, reach) > probes.size() / 2);
}

TEST_CASE("under local the end of a drag maps the points exactly, as the replay ends; a stop changes nothing") {
  EditSession<2> session = circle_with_two_handles();
  session.set_resampling(true, ResamplePolicy::parse("local"));
  session.begin_drag();
  std::vector<Vec<2>> to = session.handles();
  for (int k = 1; k <= 3; ++k) {
    to[1].x() = 1.0 + 0.002 * k;  // mild: no step resamples, the points stay interpolated
    REQUIRE(session.move_handles(to, kRunAll).stepped);
  }
  const PointSet<2> interpolated = session.points();
  const std::uint64_t version = session.version();
  const WorkControl stop{[] { return true; }, {}};
  CHECK_FALSE(session.map_exactly(stop));
  CHECK(session.version() == version);
  CHECK(session.points().positions == interpolated.positions);
  REQUIRE(session.map_exactly(kRunAll));
  CHECK(session.version() != version);
  CHECK(session.points().positions != interpolated.positions);
  CHECK_FALSE(session.map_exactly(kRunAll));  // exact already
  const PointSet<2> replayed = amls::test::replay_with_amls_deform(session.recording());
  CHECK(sorted(replayed.positions) == sorted(session.points().positions));
  CHECK(sorted(session.evaluable_surface().points().positions) == sorted(session.points().positions));
}

TEST_CASE("under local the loaded points can be resampled before the first step, which then only maps") {
  EditSession<2> session = circle_with_two_handles();
  CHECK_FALSE(session.prepare_local(kRunAll).changed);  // always: nothing to prepare
  session.set_resampling(true, ResamplePolicy::parse("local"));
  const WorkControl stop{[] { return true; }, {}};
  const std::uint64_t loaded = session.version();
  CHECK(session.prepare_local(stop).cancelled);
  CHECK(session.version() == loaded);
  const EditResult prepared = session.prepare_local(kRunAll);
  REQUIRE(prepared.changed);
  CHECK(prepared.resamples == 1);
  CHECK(session.version() != loaded);
  CHECK_FALSE(session.prepare_local(kRunAll).changed);  // the loop holds the points
  std::vector<std::string> names;
  const WorkControl control{{}, [&](const char* name, int, int) { names.push_back(name); }};
  session.begin_drag();
  std::vector<Vec<2>> to = session.handles();
  to[1].x() = 1.15;
  REQUIRE(session.move_handles(to, control).stepped);
  CHECK(names == std::vector<std::string>{"deforming, resampling where strained"});
  // The same points as a session whose first step resampled them.
  EditSession<2> reference = circle_with_two_handles();
  reference.set_resampling(true, ResamplePolicy::parse("local"));
  reference.begin_drag();
  REQUIRE(reference.move_handles(to, kRunAll).stepped);
  CHECK(sorted(session.points().positions) == sorted(reference.points().positions));
  session.map_exactly(kRunAll);  // as the replay ends
  CHECK(sorted(amls::test::replay_with_amls_deform(session.recording()).positions) ==
        sorted(session.points().positions));
}
