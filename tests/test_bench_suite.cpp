#include <doctest/doctest.h>

#include "core/run/bench_suite.hpp"

using namespace amls;

TEST_CASE("bench: one step on a sampled sphere keeps about the requested number of points and times every phase") {
  const BenchCase c = bench_sphere_step(5000, 2);
  CHECK(c.points > 3500);
  CHECK(c.points < 7000);
  CHECK(seconds_of(c.timings, "normals") > 0.0);
  CHECK(seconds_of(c.timings, "function") > 0.0);
  CHECK(seconds_of(c.timings, "resample") > 0.0);
  CHECK(c.points_per_second() > 0.0);
  CHECK(c.peak_memory_mib > 0.0);
  CHECK(c.threads == 2);
}
