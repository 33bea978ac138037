// The regions' gaps measured once and given to the map (MlsDeformation::
// region_gaps, local_map with gaps) and kept by a rest lattice from one map to
// the next: the same results, bit for bit, as searching the members each time.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/deform/mls_lattice.hpp"
#include "core/util/thread_pool.hpp"
#include "region_fixtures.hpp"

using namespace amls;

namespace {

constexpr double kH = 0.05;

RegionMotion<3> moved(double lift, double turn) {
  RegionMotion<3> m;
  m.translation = Vec<3>(0.0, 0.02, lift);
  m.rotation = Vec<3>(turn, 0.0, 0.0);
  return m;
}

// The south cap pinned and the north cap from `first` to `second`, with one point handle on the equator.
MlsDeformation<3> caps_map(const RegionMotion<3>& first, const RegionMotion<3>& second) {
  static const auto south = test::sphere_cap(kH, -1.0, 0.6);
  static const auto north = test::sphere_cap(kH, 1.0, 0.6);
  MlsDeformation<3> map({Vec<3>(1, 0, 0)}, {Vec<3>(1.02, 0, 0)}, {{south, {}, true}, {north, first, false}},
                        {{south, {}, true}, {north, second, false}});
  map.use_polar_iteration(true);
  return map;
}

bool same_bits(const PointSet<3>& a, const PointSet<3>& b) { return a.positions == b.positions && a.normals == b.normals; }

}  // namespace

TEST_CASE("region gaps: given or searched, the local map is the same bit for bit, and their least is region_gap") {
  const MlsDeformation<3> map = caps_map(moved(0.1, 0.2), moved(0.3, 0.5));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
  std::size_t within = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec<3> v(coordinate(random), coordinate(random), coordinate(random));
    std::vector<double> gaps(2);
    map.region_gaps(v, gaps);
    CHECK(*std::min_element(gaps.begin(), gaps.end()) == map.region_gap(v));
    within += *std::min_element(gaps.begin(), gaps.end()) <= 0.0 ? 1 : 0;
    const MlsLocalMap<3> searched = map.local_map(v), given = map.local_map(v, gaps);
    CHECK(searched.position == given.position);
    CHECK(searched.linear == given.linear);
  }
  // Near the caps too: points within reach take the motion from the gaps given.
  // Held here: a range-for over a temporary's members would read them after the region is freed.
  const auto cap = test::sphere_cap(kH, 1.0, 0.6);
  for (const Vec<3>& m : cap->members()) {
    const Vec<3> v = moved(0.1, 0.2).linear() * m + moved(0.1, 0.2).offset(cap->centre());
    std::vector<double> gaps(2);
    map.region_gaps(v, gaps);
    CHECK(map.local_map(v).position == map.local_map(v, gaps).position);
    if (m.z() > 0.99) break;
  }
  MESSAGE(within << " of 2000 random points within a region's reach");
  std::vector<double> wrong(3);
  CHECK_THROWS_AS(map.region_gaps(Vec<3>::Zero(), wrong), std::invalid_argument);
  CHECK_THROWS_AS(map.local_map(Vec<3>::Zero(), wrong), std::invalid_argument);
}

TEST_CASE("region gaps: a rest lattice that keeps them maps as a fresh one does, and measures them anew for new places") {
  ThreadPool pool(2);
  const PointSet<3> rest = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points_for_spacing(1.0, kH));
  const MlsLatticeOptions options{8.0 * kH, 0.001 * kH, 4, true};
  const MlsRestLattice<3> kept(rest, options, pool);
  auto fresh = [&](const MlsDeformation<3>& map) {
    PointSet<3> out;
    MlsRestLattice<3>(rest, options, pool).map(map, rest, out, nullptr, nullptr, pool);
    return out;
  };
  PointSet<3> out;
  // The first map measures the gaps, the second (the same first places) reuses them.
  for (const double lift : {0.05, 0.2}) {
    const MlsDeformation<3> map = caps_map(RegionMotion<3>{}, moved(lift, 0.1));
    const MlsLatticeStats stats = kept.map(map, rest, out, nullptr, nullptr, pool);
    CHECK(stats.exact_points > 0);  // the points within the caps' reach
    CHECK(same_bits(out, fresh(map)));
  }
  // Other first places: the gaps kept are not theirs.
  const MlsDeformation<3> from_moved = caps_map(moved(0.2, 0.1), moved(0.3, 0.2));
  kept.map(from_moved, rest, out, nullptr, nullptr, pool);
  CHECK(same_bits(out, fresh(from_moved)));
  // And a map without regions after them.
  const MlsDeformation<3> points_only({Vec<3>(0, 0, 1)}, {Vec<3>(0, 0, 1.1)});
  kept.map(points_only, rest, out, nullptr, nullptr, pool);
  CHECK(same_bits(out, fresh(points_only)));
}
