#include <doctest/doctest.h>

#include <cmath>

#include "core/math/root_finding.hpp"
#include "core/resample/segment_root.hpp"

using namespace amls;

namespace {

RootOptions tolerance(double t) {
  RootOptions options;
  options.tolerance = t;
  return options;
}

}  // namespace

TEST_CASE("find_root finds a bracketed root to the requested tolerance without slopes") {
  auto g = [](double t) -> std::optional<RootSample> { return RootSample{t * t * t - 0.2}; };
  const RootResult r = find_root(g, 0.0, 1.0, -0.2, 0.8, tolerance(1e-13));
  REQUIRE(r.ok);
  CHECK(r.t == doctest::Approx(std::cbrt(0.2)).epsilon(1e-12));
  CHECK(r.evaluations < 20);
}

TEST_CASE("find_root converges in a few steps from a good guess with slopes") {
  const double root = std::cbrt(0.2);
  auto g = [](double t) -> std::optional<RootSample> { return RootSample{t * t * t - 0.2, 3.0 * t * t}; };
  RootOptions options = tolerance(1e-13);
  options.first_guess = root + 1e-3;
  const RootResult r = find_root(g, 0.0, 1.0, -0.2, 0.8, options);
  REQUIRE(r.ok);
  CHECK(r.t == doctest::Approx(root).epsilon(1e-12));
  CHECK(r.evaluations <= 5);
}

TEST_CASE("find_root takes a short enough step's end as the root without evaluating it") {
  // The slope estimate is 10 % off, as a fit's gradient may be: Newton's step
  // from a guess 1e-7 off leaves about a tenth of that.
  const double root = std::cbrt(0.2);
  int evaluations = 0;
  auto g = [&](double t) -> std::optional<RootSample> {
    ++evaluations;
    return RootSample{t * t * t - 0.2, 1.1 * 3.0 * t * t};
  };
  RootOptions options = tolerance(1e-13);
  options.first_guess = root + 1e-7;
  options.step_tolerance = 1e-5;
  const RootResult quick = find_root(g, 0.0, 1.0, -0.2, 0.8, options);
  REQUIRE(quick.ok);
  CHECK(quick.evaluations == 1);
  CHECK(evaluations == 1);
  CHECK(std::abs(quick.t - root) < 2e-8);
  CHECK(std::abs(quick.t - root) > 1e-12);  // not evaluated there: not converged to the tolerance
  // Without the step tolerance the search goes on to the tolerance.
  options.step_tolerance = 0.0;
  const RootResult full = find_root(g, 0.0, 1.0, -0.2, 0.8, options);
  REQUIRE(full.ok);
  CHECK(full.evaluations > 1);
  CHECK(full.t == doctest::Approx(root).epsilon(1e-12));
}

TEST_CASE("find_root still converges where the secant steps are poor") {
  // Nearly a step function: secants through samples on the flat parts shoot
  // far off, so the bracket safeguards must do the work.
  auto g = [](double t) -> std::optional<RootSample> { return RootSample{std::tanh(200.0 * (t - 0.3141))}; };
  const RootResult r = find_root(g, 0.0, 1.0, std::tanh(-200.0 * 0.3141), std::tanh(200.0 * 0.6859), tolerance(1e-12));
  REQUIRE(r.ok);
  CHECK(r.t == doctest::Approx(0.3141).epsilon(1e-10));
  CHECK(r.evaluations < 100);
}

TEST_CASE("find_root returns an end whose value is exactly zero") {
  auto g = [](double) -> std::optional<RootSample> { return RootSample{1.0}; };
  CHECK(find_root(g, 0.0, 1.0, 0.0, -1.0, tolerance(1e-12)).t == 0.0);
  CHECK(find_root(g, 0.0, 1.0, -1.0, 0.0, tolerance(1e-12)).t == 1.0);
}

TEST_CASE("find_root reports failure where the function is undefined") {
  auto g = [](double t) -> std::optional<RootSample> {
    if (t > 0.3 && t < 0.7) return std::nullopt;
    return RootSample{t - 0.5};
  };
  CHECK_FALSE(find_root(g, 0.0, 1.0, -0.5, 0.5, tolerance(1e-12)).ok);
}

TEST_CASE("the Hermite guess recovers a cubic's root exactly and falls back outside the segment") {
  // p(t) = (t - 0.3)(t + 1)(t + 2): values and slopes at 0 and 1.
  auto p = [](double t) { return (t - 0.3) * (t + 1.0) * (t + 2.0); };
  auto dp = [](double t) { return (t + 1.0) * (t + 2.0) + (t - 0.3) * (2.0 * t + 3.0); };
  const double linear = p(0.0) / (p(0.0) - p(1.0));
  CHECK(hermite_root_guess(p(0.0), p(1.0), dp(0.0), dp(1.0), linear) == doctest::Approx(0.3).epsilon(1e-10));
  // Slopes that contradict the values send Newton off the segment: no guess.
  CHECK(std::isnan(hermite_root_guess(-1.0, 1.0, -20.0, -20.0, 0.1)));
}

TEST_CASE("find_root stops early at a jump that is not a zero and says so") {
  // A step from -1 to +1 at 0.3141: no root, only a discontinuity. Bisecting
  // to 1e-12 would take about 40 more evaluations.
  auto g = [](double t) -> std::optional<RootSample> { return RootSample{t < 0.3141 ? -1.0 - t : 1.0 + t}; };
  const RootResult r = find_root(g, 0.0, 1.0, -1.0, 2.0, tolerance(1e-12));
  REQUIRE(r.ok);
  CHECK(r.jump);
  CHECK(r.t == doctest::Approx(0.3141).epsilon(0.01));
  CHECK(r.evaluations <= kFastSteps + 8);
  // A smooth function is never taken for a jump, however steep.
  auto steep = [](double t) -> std::optional<RootSample> { return RootSample{std::tanh(200.0 * (t - 0.3141))}; };
  CHECK_FALSE(find_root(steep, 0.0, 1.0, std::tanh(-200.0 * 0.3141), std::tanh(200.0 * 0.6859), tolerance(1e-12)).jump);
}

TEST_CASE("find_root ends on a secant step it need not evaluate when convergence shows it is within tolerance") {
  const double root = std::cbrt(0.2);
  int calls = 0;
  auto g = [&](double t) -> std::optional<RootSample> {
    ++calls;
    return RootSample{t * t * t - 0.2, 3.0 * t * t};
  };
  RootOptions options = tolerance(1e-12);
  options.first_guess = root + 1e-4;
  const RootResult r = find_root(g, 0.0, 1.0, -0.2, 0.8, options);
  REQUIRE(r.ok);
  CHECK(r.evaluations == calls);
  CHECK(std::abs(r.t - root) < 1e-12);
  CHECK(r.evaluations <= 3);
}
