#include <doctest/doctest.h>

#include <stdexcept>

#include "core/deform/deformation_history.hpp"

using namespace amls;

namespace {

// Two stages: one handle moving right in 2 + 2 steps, then two handles (one added) moving up in 3.
DeformationHistory<2> two_stages() {
  DeformationHistory<2> h;
  h.begin_stage({Vec<2>(0, 0)});
  h.add_target({Vec<2>(1, 0)}, 2);
  h.add_target({Vec<2>(1, 2)}, 2);
  h.begin_stage({Vec<2>(1, 2), Vec<2>(5, 5)});
  h.add_target({Vec<2>(1, 5), Vec<2>(5, 8)}, 3);
  return h;
}

}  // namespace

TEST_CASE("history: steps interpolate handles linearly between configurations, stage by stage") {
  const DeformationHistory<2> h = two_stages();
  REQUIRE_NOTHROW(h.validate());
  CHECK(h.total_steps() == 7);
  CHECK(h.stages[0].handles_after(1)[0].isApprox(Vec<2>(0.5, 0)));
  CHECK(h.stages[0].handles_after(2)[0] == Vec<2>(1, 0));  // targets are reached exactly
  CHECK(h.stages[0].handles_after(3)[0].isApprox(Vec<2>(1, 1)));
  const HistoryStep<2> s = h.step(1, 1);  // second stage, second step
  CHECK(s.index == 5);
  CHECK(s.from[0].isApprox(Vec<2>(1, 3)));
  CHECK(s.to[0].isApprox(Vec<2>(1, 4)));
  CHECK(s.to[1].isApprox(Vec<2>(5, 7)));
  // The global index and the (stage, step) pair name the same step.
  const HistoryStep<2> g = h.step(5);
  CHECK(g.stage == 1);
  CHECK(g.step_in_stage == 1);
  CHECK(g.from == s.from);
  CHECK_THROWS_AS(h.step(7), std::out_of_range);
  CHECK_THROWS_AS(h.step(0, 4), std::out_of_range);
}

TEST_CASE("history: the iterator walks every step in order, each starting where the last ended") {
  const DeformationHistory<2> h = two_stages();
  std::size_t count = 0;
  std::vector<Vec<2>> previous;
  std::size_t previous_stage = 0;
  for (const HistoryStep<2> s : h.steps()) {
    CHECK(s.index == count);
    if (count > 0 && s.stage == previous_stage) CHECK(s.from == previous);
    previous = s.to;
    previous_stage = s.stage;
    ++count;
  }
  CHECK(count == h.total_steps());
  CHECK(previous[1] == Vec<2>(5, 8));
}

TEST_CASE("history: validation names the stage and target at fault") {
  DeformationHistory<2> h = two_stages();
  CHECK_THROWS_WITH_AS(h.add_target({Vec<2>(0, 0)}, 1), doctest::Contains("starts a new stage"), std::invalid_argument);
  h.stages[1].targets[0].handles.pop_back();
  CHECK_THROWS_WITH_AS(h.validate(), doctest::Contains("stages[1].targets[0].handles: 1 handles, but the stage has 2"),
                       std::invalid_argument);
  h = two_stages();
  h.stages[0].targets[1].steps = 0;
  CHECK_THROWS_WITH(h.validate(), doctest::Contains("stages[0].targets[1].steps"));
  h = two_stages();
  h.stages[1].start[1].y() = std::nan("");
  CHECK_THROWS_WITH(h.validate(), doctest::Contains("stages[1].handles[1][1]: not a finite number"));
  h = two_stages();
  h.stages[0].targets.clear();
  CHECK_THROWS_WITH(h.validate(), doctest::Contains("stages[0].targets: a stage needs at least one target"));
  CHECK_THROWS_WITH(DeformationHistory<3>{}.validate(), doctest::Contains("no stage"));
}
