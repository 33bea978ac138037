#include <doctest/doctest.h>

#include "core/flow_test.hpp"
#include "core/resample_policy.hpp"
#include "core/shapes.hpp"

using namespace amls;

TEST_CASE("resample policies parse, print, and reject bad forms with a message") {
  CHECK(ResamplePolicy::parse("always").kind == ResamplePolicy::Kind::always);
  CHECK(ResamplePolicy::parse("auto").kind == ResamplePolicy::Kind::automatic);
  const ResamplePolicy every = ResamplePolicy::parse("every:5");
  CHECK(every.kind == ResamplePolicy::Kind::every);
  CHECK(every.every == 5);
  CHECK(every.to_string() == "every:5");
  for (const char* bad : {"sometimes", "every:", "every:0", "every:3x", "every:-2"})
    CHECK_THROWS_WITH_AS(ResamplePolicy::parse(bad), doctest::Contains("always, auto or every:K"), std::invalid_argument);
}

TEST_CASE("auto resamples when the spacing leaves its band, and not before") {
  const ResamplePolicy policy = ResamplePolicy::parse("auto");
  const double h = 0.01;
  // 0.2 circumference / 150 points: spacing 0.84 h, inside [0.25, 2].
  const PointSet<2> even = sample_circle(Vec<2>(0.5, 0.5), 0.2, 150);
  CHECK_FALSE(policy.resample_now<2>(3, even, h));
  CHECK(policy.resample_now<2>(0, even, h));  // the first step always resamples
  // Stretched: 40 points on the same circle are 3.1 h apart.
  CHECK(policy.resample_now<2>(3, sample_circle(Vec<2>(0.5, 0.5), 0.2, 40), h));
  // Crowded: 1000 points are 0.13 h apart.
  CHECK(policy.resample_now<2>(3, sample_circle(Vec<2>(0.5, 0.5), 0.2, 1000), h));
}

TEST_CASE("the flow test counts its resamples under every policy") {
  FlowTestConfig config;
  config.grid = 64;
  config.dt = 0.04;
  config.resample = ResamplePolicy::parse("every:4");
  const FlowTestReport r = run_vortex_test(config).report;
  CHECK(r.resamples == 50);  // steps 0, 4, ..., 196 of 200
  config.resample = ResamplePolicy::parse("auto");
  const FlowTestReport a = run_vortex_test(config).report;
  CHECK(a.resamples >= 1);
  CHECK(a.resamples < 200);
}
