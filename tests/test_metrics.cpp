#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/surface/block_sample.hpp"
#include "core/surface/metrics.hpp"
#include "core/geometry/shapes.hpp"
#include "surface_fixtures.hpp"

using namespace amls;

TEST_CASE("metrics: per-point nearest-neighbour spacing stays with its point") {
  // Three points on a line, 1 and 3 h apart, and a fourth 0.5 h from the last.
  PointSet<2> points;
  const double h = 0.1;
  for (double x : {0.0, 0.1, 0.4, 0.45}) points.add(Vec<2>(x, 0.0), Vec<2>(0.0, 1.0));
  const std::vector<double> s = nearest_neighbour_spacing_per_point(points, h);
  REQUIRE(s.size() == 4);
  CHECK(s[0] == doctest::Approx(1.0));
  CHECK(s[1] == doctest::Approx(1.0));
  CHECK(s[2] == doctest::Approx(0.5));
  CHECK(s[3] == doctest::Approx(0.5));
  CHECK(nearest_neighbour_spacing_per_point(PointSet<2>{}, h).empty());
}

TEST_CASE("metrics: per-point spacing with a lone far point: exact, and the same on any thread count") {
  // A circle of points h apart and one point 1e6 h away: its search would
  // widen over ever more cells; it scans the points instead.
  const double h = 0.01;
  PointSet<2> points = sample_circle(Vec<2>(0.5, 0.5), 0.3, 200);
  points.add(Vec<2>(1e4, 0.5), Vec<2>(0.0, 1.0));
  ThreadPool one(1), two(2);
  const std::vector<double> a = nearest_neighbour_spacing_per_point(points, h, one);
  const std::vector<double> b = nearest_neighbour_spacing_per_point(points, h, two);
  REQUIRE(a.size() == points.size());
  CHECK(a == b);
  double expected = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j + 1 < points.size(); ++j)
    expected = std::min(expected, (points.positions[j] - points.positions.back()).norm() / h);
  CHECK(a.back() == doctest::Approx(expected));
}

TEST_CASE("metrics: nearest distances between two sets, in units of h") {
  const PointSet<2> circle = sample_circle(Vec<2>::Zero(), 1.0, 400);
  const PointSet<2> bigger = sample_circle(Vec<2>::Zero(), 1.1, 4000);
  const DistanceStats d = nearest_distance_stats(circle.positions, bigger.positions, 0.05);
  CHECK(d.count == 400);
  CHECK(d.mean == doctest::Approx(2.0).epsilon(0.01));  // 0.1 apart = 2 h
  CHECK(d.max == doctest::Approx(2.0).epsilon(0.01));
  CHECK(nearest_distance_stats(circle.positions, circle.positions, 0.05).max == 0.0);
  CHECK_THROWS(nearest_distance_stats(circle.positions, std::vector<Vec<2>>{}, 0.05));
  const std::vector<double> spacings = nearest_neighbour_spacings(circle, 0.01);
  CHECK(spacings.size() == 400);
  CHECK(spacing_stats_of(spacings).median == doctest::Approx(2.0 * std::sin(3.14159265358979 / 400) / 0.01));
}

TEST_CASE("metrics: the L1 error of a sampled circle against a concentric circle is the annulus area") {
  ThreadPool pool(2);
  const Vec<2> c(0.5, 0.5);
  const auto s = amls::test::ready_surface(sample_circle(c, 0.2, 300), Grid<2>::unit(128), pool);
  const CircleError same = circle_l1_error(s, c, 0.2, pool, 4096);
  CHECK(same.scan.closed);
  CHECK(same.l1 < 1e-9);
  const CircleError wider = circle_l1_error(s, c, 0.21, pool, 4096);
  CHECK(wider.l1 == doctest::Approx(M_PI * (0.21 * 0.21 - 0.2 * 0.2)).epsilon(1e-6));
}

TEST_CASE("metrics: the volume of a sampled sphere, and its symmetric difference with a smaller one") {
  ThreadPool pool(2);
  const Vec<3> c(0.5, 0.5, 0.5);
  const auto s = amls::test::ready_surface(sample_sphere(c, 0.2, 6000), Grid<3>::unit(64), pool);
  const SphereError e = sphere_volume_error(s, c, 0.18, pool, 2000);
  CHECK(e.scan.closed);
  const double v = 4.0 / 3.0 * M_PI * 0.2 * 0.2 * 0.2;
  CHECK(e.volume == doctest::Approx(v).epsilon(1e-6));
  CHECK(e.symmetric_difference == doctest::Approx(v - e.exact_volume).epsilon(1e-6));
}

TEST_CASE("metrics: a curve with a gap is not one closed curve") {
  ThreadPool pool(1);
  PointSet<2> arc = sample_circle(Vec<2>(0.5, 0.5), 0.2, 300);
  arc.positions.resize(200);  // two thirds of the circle
  arc.normals.resize(200);
  const auto s = amls::test::ready_surface(std::move(arc), Grid<2>::unit(128), pool);
  const CircleError e = circle_l1_error(s, Vec<2>(0.5, 0.5), 0.2, pool, 1024);
  CHECK_FALSE(e.scan.closed);
  CHECK(e.scan.bad_rays > 100);
  CHECK_FALSE(e.scan.reason.empty());
}

TEST_CASE("metrics: a frame's spacing summary: every point's as the sorted spacings say, or an even sample's") {
  // A sphere sampled unevenly enough that spacings differ, some outside [0.3 h, 1.5 h].
  const double h = 0.01;
  PointSet<3> points = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 20000);
  for (std::size_t i = 0; i < 200; ++i) points.add(points.positions[i] + Vec<3>(0.001, 0.0, 0.0), points.normals[i]);
  ThreadPool one(1), three(3);
  const std::vector<double> every = nearest_neighbour_spacing_per_point(points, h, three);
  SUBCASE("all points: the figures of the sorted spacings") {
    std::vector<double> sorted = every;
    std::sort(sorted.begin(), sorted.end());
    const SpacingStats expected = spacing_stats_of(sorted);
    const SpacingSummary s = spacing_summary(points, h, points.size(), three);
    CHECK_FALSE(s.sampled());
    CHECK(s.measured == points.size());
    CHECK(s.of == points.size());
    CHECK(s.h.min == expected.min);
    CHECK(s.h.median == expected.median);
    CHECK(s.h.max == expected.max);
    const auto below = static_cast<std::size_t>(std::count_if(sorted.begin(), sorted.end(), [](double d) { return d < 0.3; }));
    const auto above = static_cast<std::size_t>(std::count_if(sorted.begin(), sorted.end(), [](double d) { return d > 1.5; }));
    CHECK(below >= 200);  // the added pairs, 0.1 h apart
    CHECK(s.below == below);
    CHECK(s.above == above);
  }
  SUBCASE("a sample: about one point in ceil(n / 1000), each at its exact spacing, the same for any thread count") {
    const SpacingSummary s = spacing_summary(points, h, 1000, one);
    CHECK(s.sampled());
    CHECK(s.of == points.size());
    // Blocks of about 110 points here, one in 21 of the 180: a handful of blocks (380 points).
    CHECK(s.measured > 100);
    CHECK(s.measured < 4000);
    // Every figure is some point's exact spacing.
    for (const double d : {s.h.min, s.h.median, s.h.max}) CHECK(std::find(every.begin(), every.end(), d) != every.end());
    const SpacingSummary t = spacing_summary(points, h, 1000, three);
    CHECK(t.measured == s.measured);
    CHECK(t.h.min == s.h.min);
    CHECK(t.h.median == s.h.median);
    CHECK(t.h.max == s.h.max);
    CHECK(t.below == s.below);
    CHECK(t.above == s.above);
  }
  SUBCASE("a sample of points farther apart than 2 h: measured against every point") {
    // A grid of points 3 h apart: no sampled point has a candidate within reach.
    PointSet<3> sparse;
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j)
        for (int k = 0; k < 20; ++k) sparse.add(3.0 * h * Vec<3>(i, j, k), Vec<3>::UnitZ());
    const SpacingSummary s = spacing_summary(sparse, h, 1000, three);
    CHECK(s.sampled());
    CHECK(s.h.min == doctest::Approx(3.0));
    CHECK(s.h.max == doctest::Approx(3.0));
    CHECK(s.above == s.measured);
  }
  SUBCASE("fewer than two points measure nothing") {
    PointSet<3> lone;
    lone.add(Vec<3>::Zero(), Vec<3>::UnitZ());
    const SpacingSummary s = spacing_summary(lone, h, 1000, three);
    CHECK(s.measured == 0);
    CHECK(s.of == 1);
    CHECK_FALSE(s.sampled());
  }
}

TEST_CASE("metrics: nearest distances on a pool have the same bits for any thread count") {
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 30000);
  const PointSet<3> bigger = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.31, 5000);
  const DistanceStats serial = nearest_distance_stats(sphere.positions, bigger.positions, 0.01);
  CHECK(serial.count == 30000);
  CHECK(serial.mean > 1.0);  // at least the radii's 0.01 apart, 1 h
  for (const int threads : {2, 3, 8}) {
    ThreadPool pool(threads);
    const DistanceStats d = nearest_distance_stats(sphere.positions, bigger.positions, 0.01, pool);
    CHECK(d.count == serial.count);
    CHECK(d.mean == serial.mean);
    CHECK(d.max == serial.max);
  }
}

TEST_CASE("metrics: nearest distances from a block sample: each the exact one, the same for any thread count") {
  const double h = 0.01;
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 30000);
  const PointSet<3> bigger = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.305, 20000);
  ThreadPool one(1), three(3);
  const DistanceStats all = nearest_distance_stats(sphere.positions, bigger.positions, h, three);
  SUBCASE("no more than max_measured: every point, as without a limit") {
    const DistanceStats d = nearest_distance_stats(sphere.positions, bigger.positions, h, sphere.size(), three);
    CHECK(d.count == all.count);
    CHECK(d.mean == all.mean);
    CHECK(d.max == all.max);
  }
  SUBCASE("a sample of about max_measured, within the whole set's figures") {
    const DistanceStats d = nearest_distance_stats(sphere.positions, bigger.positions, h, 3000, one);
    CHECK(d.count > 300);
    CHECK(d.count < 10000);
    // Each sampled distance is a point's exact one: the largest at most all points' largest.
    CHECK(d.max <= all.max);
    CHECK(d.max > 0.5 * all.max);
    // The radii are 0.5 h apart and the bigger sphere's points about 1.2 h: the mean of a
    // sample spread over the sphere is within a few percent of all points' (here 0.76 h).
    CHECK(d.mean == doctest::Approx(all.mean).epsilon(0.05));
    const DistanceStats t = nearest_distance_stats(sphere.positions, bigger.positions, h, 3000, three);
    CHECK(t.count == d.count);
    CHECK(t.mean == d.mean);
    CHECK(t.max == d.max);
  }
  SUBCASE("sampled points with nothing within 2 h are measured against every point") {
    const PointSet<3> far = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.35, 20000);  // 5 h out
    const DistanceStats whole = nearest_distance_stats(sphere.positions, far.positions, h, three);
    const DistanceStats d = nearest_distance_stats(sphere.positions, far.positions, h, 3000, three);
    CHECK(d.count > 300);
    CHECK(d.max <= whole.max);
    CHECK(d.mean == doctest::Approx(whole.mean).epsilon(0.05));
    CHECK(d.mean > 4.9);
  }
}

TEST_CASE("metrics: a block sample's blocks are those whose hash is a multiple of `every`") {
  // The sample tests divisibility by a multiplication (block_sample.hpp): the
  // blocks it takes must be those a remainder would.
  for (const std::uint64_t every : {1ULL, 2ULL, 3ULL, 7ULL, 10ULL, 50ULL, 64ULL, 96ULL, 1000003ULL}) {
    const BlockSample<3> sample(1.0, every);
    std::size_t taken = 0, wrong = 0;
    for (std::int64_t x = -20; x < 20; ++x)
      for (std::int64_t y = -20; y < 20; ++y)
        for (std::int64_t z = -5; z < 5; ++z) {
          const IVec<3> block(x, y, z);
          const bool expected = block_hash(Grid<3>::key(block)) % every == 0;
          wrong += sample.sampled(block) == expected ? 0 : 1;
          taken += expected ? 1 : 0;
        }
    CAPTURE(every);
    CHECK(wrong == 0);
    if (every <= 100) CHECK(taken > 16000 / every / 2);  // the hash spreads the sample
  }
  CHECK_THROWS_AS(BlockSample<3>(1.0, 0), std::invalid_argument);
}

namespace {

// A point's place against a block sample from its definition: its own block
// sampled, else some other sampled block whose box grown by `reach` holds it.
template <int D>
BlockPlace place_by_definition(const BlockSample<D>& sample, const Vec<D>& p, double reach) {
  const double side = sample.side();
  IVec<D> block;
  for (int a = 0; a < D; ++a) block[a] = static_cast<std::int64_t>(std::floor(p[a] / side));
  if (sample.sampled(block)) return BlockPlace::inside;
  bool near = false;
  for_each_index_in_box<D>(block - IVec<D>::Ones(), block + IVec<D>::Ones(), [&](const IVec<D>& b) {
    bool held = true;
    for (int a = 0; a < D; ++a)
      held = held && side * static_cast<double>(b[a]) - reach < p[a] && p[a] < side * static_cast<double>(b[a] + 1) + reach;
    near = near || (held && sample.sampled(b));
  });
  return near ? BlockPlace::near : BlockPlace::away;
}

template <int D>
void check_places_against_definition() {
  const BlockSample<D> sample(1.0, 5);
  const double reach = 0.25;
  std::uint64_t state = 12345;
  auto uniform = [&] {
    state = block_hash(state + 0x9e3779b97f4a7c15ULL);
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  // Points in runs of a few per block (as a resample writes them), then
  // shuffled, so the remembered neighbourhood is both reused and begun again.
  std::vector<Vec<D>> points;
  for (int run = 0; run < 4000; ++run) {
    Vec<D> corner;
    for (int a = 0; a < D; ++a) corner[a] = std::floor(uniform() * 40.0 - 20.0);
    for (int k = 0; k < 6; ++k) {
      Vec<D> p;
      for (int a = 0; a < D; ++a) p[a] = corner[a] + uniform();
      points.push_back(p);
    }
  }
  std::vector<Vec<D>> shuffled = points;
  for (std::size_t i = shuffled.size(); i > 1; --i) std::swap(shuffled[i - 1], shuffled[static_cast<std::size_t>(uniform() * static_cast<double>(i))]);
  std::size_t counts[3] = {0, 0, 0}, wrong = 0;
  for (const auto* order : {&points, &shuffled}) {
    typename BlockSample<D>::Neighbourhood seen;
    for (const Vec<D>& p : *order) {
      const BlockPlace expected = place_by_definition(sample, p, reach);
      wrong += sample.place(p, reach, seen) == expected ? 0 : 1;
      typename BlockSample<D>::Neighbourhood fresh;
      wrong += sample.place(p, reach, fresh) == expected ? 0 : 1;
      ++counts[static_cast<int>(expected)];
    }
  }
  CHECK(wrong == 0);
  // All three places occur, so the check covers each.
  CHECK(counts[static_cast<int>(BlockPlace::away)] > 0);
  CHECK(counts[static_cast<int>(BlockPlace::near)] > 0);
  CHECK(counts[static_cast<int>(BlockPlace::inside)] > 0);
}

}  // namespace

TEST_CASE("metrics: a block sample places points as its definition says, remembering a block's neighbours or not") {
  check_places_against_definition<2>();
  check_places_against_definition<3>();
}
