#include <doctest/doctest.h>

#include <cmath>

#include "core/root_finding.hpp"

using namespace amls;

TEST_CASE("Illinois finds a bracketed root to the requested tolerance") {
  auto g = [](double t) -> std::optional<double> { return t * t * t - 0.2; };
  const RootResult r = find_root_illinois(g, 0.0, 1.0, -0.2, 0.8, 1e-13);
  REQUIRE(r.ok);
  CHECK(r.t == doctest::Approx(std::cbrt(0.2)).epsilon(1e-12));
  CHECK(r.evaluations < 20);
}

TEST_CASE("Illinois returns an end whose value is exactly zero") {
  auto g = [](double) -> std::optional<double> { return 1.0; };
  CHECK(find_root_illinois(g, 0.0, 1.0, 0.0, -1.0, 1e-12).t == 0.0);
  CHECK(find_root_illinois(g, 0.0, 1.0, -1.0, 0.0, 1e-12).t == 1.0);
}

TEST_CASE("Illinois reports failure where the function is undefined") {
  auto g = [](double t) -> std::optional<double> {
    if (t > 0.3 && t < 0.7) return std::nullopt;
    return t - 0.5;
  };
  CHECK_FALSE(find_root_illinois(g, 0.0, 1.0, -0.5, 0.5, 1e-12).ok);
}
