#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/run/settle.hpp"

using namespace amls;

namespace {

// A circle of 400 points, denser than a resample on the unit grid of 128 cells makes.
PointSet<2> dense_circle() { return sample_circle(Vec<2>(0.5, 0.5), 0.25, 400); }

}  // namespace

TEST_CASE("settle: the policy decides, and S(P) is resampled in place only when it says so") {
  SUBCASE("every:2 resamples on step 0 and 2, not on step 1") {
    const ResamplePolicy policy = ResamplePolicy::parse("every:2");
    DeformingSurface<2> surface(Grid<2>::unit(128), AmlsParameters{}, Variant::exact);
    surface.set_points(dense_circle());
    const std::optional<Settling> first = settle(surface, policy, 0);
    REQUIRE(first);
    CHECK(first->resampled);
    CHECK(first->stats.points_before == 400);
    CHECK(first->stats.points_after == surface.points().size());
    CHECK(surface.points().size() != 400);  // the resampler's own points
    const PointSet<2> resampled = surface.points();
    const std::optional<Settling> second = settle(surface, policy, 1);
    REQUIRE(second);
    CHECK_FALSE(second->resampled);
    CHECK(second->stats.points_before == 0);  // no work
    CHECK(surface.points().positions == resampled.positions);
    CHECK(settle(surface, policy, 2)->resampled);
  }
  SUBCASE("the gate hears of each phase that does work, and stopping there leaves the points as they were") {
    const ResamplePolicy policy = ResamplePolicy::parse("auto");
    DeformingSurface<2> surface(Grid<2>::unit(128), AmlsParameters{}, Variant::exact);
    surface.set_points(dense_circle());
    const PointSet<2> before = surface.points();
    std::vector<std::string> phases;
    auto stop_at = [&](const std::string& stop) {
      return [&phases, stop](const char* phase) {
        phases.push_back(phase);
        return phase != stop;
      };
    };
    // Step 0 always resamples without measuring: only the resampling phase.
    CHECK_FALSE(settle(surface, policy, 0, stop_at(kResamplingPhase)));
    CHECK(phases == std::vector<std::string>{kResamplingPhase});
    CHECK(surface.points().positions == before.positions);
    // Later steps measure first.
    phases.clear();
    CHECK_FALSE(settle(surface, policy, 5, stop_at(kCheckingPhase)));
    CHECK(phases == std::vector<std::string>{kCheckingPhase});
    CHECK(surface.points().positions == before.positions);
    CHECK(policy_measures(policy, 5));
    CHECK_FALSE(policy_measures(policy, 0));
    CHECK_FALSE(policy_measures(ResamplePolicy::parse("every:3"), 5));
  }
}
