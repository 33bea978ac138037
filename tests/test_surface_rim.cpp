#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "core/geometry/kd_tree.hpp"
#include "core/resample/resampler.hpp"
#include "core/resample/rim_carrying.hpp"
#include "core/surface/surface_rim.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::ready_surface;

namespace {

// Points about `spacing` apart on the part of the unit-normal sphere of
// `radius` around `center` above the plane z = center.z + cut (a cap, open
// at its rim), with outward normals: a Fibonacci lattice, as a scan's
// samples would be uneven.
PointSet<3> sample_cap(const Vec<3>& center, double radius, double cut, double spacing) {
  const std::size_t whole = sphere_points_for_spacing(radius, spacing);
  const PointSet<3> sphere = sample_sphere(center, radius, whole);
  PointSet<3> out;
  for (std::size_t k = 0; k < sphere.size(); ++k)
    if (sphere.positions[k].z() > center.z() + cut) out.add(sphere.positions[k], sphere.normals[k]);
  return out;
}

// A square patch of the plane z = z0, side 2 half, on a lattice of `spacing`
// turned by 0.3 rad against the grid, with a round hole of `hole` radius in
// its middle (none for 0); normals +z.
PointSet<3> sample_plane_patch(const Vec<3>& center, double half, double hole, double spacing) {
  PointSet<3> out;
  const double c = std::cos(0.3), s = std::sin(0.3);
  const int n = static_cast<int>(std::ceil(1.5 * half / spacing));
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      const double u = i * spacing, v = j * spacing;
      const double x = c * u - s * v, y = s * u + c * v;
      if (std::abs(x) > half || std::abs(y) > half || std::hypot(x, y) < hole) continue;
      out.add(center + Vec<3>(x, y, 0.0), Vec<3>::UnitZ());
    }
  return out;
}

PointSet<3> resample_at(const PointSet<3>& points, const Grid<3>& grid, ThreadPool& pool) {
  const AmlsSurface<3> surface = ready_surface(points, grid, pool);
  Resampler<3> resampler;
  resampler.update_function(surface, pool);
  return resampler.resample(surface, Variant::exact, pool);
}

// How many points of `a` lie farther than `distance` from every point of `b`.
std::size_t farther_than(const PointSet<3>& a, const PointSet<3>& b, double distance) {
  KdTree<3> tree;
  tree.build(b.positions);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  std::size_t count = 0;
  for (const Vec<3>& p : a.positions) {
    tree.nearest(p, 1, ids, squared);
    count += squared.at(0) > distance * distance ? 1 : 0;
  }
  return count;
}

// Resamples three times at the same h and checks the fixed point: counts
// after the first within `count_change` of it; no point of the third output
// more than 0.5 h past the first's rim, and at most `far_share` of them
// more than 0.75 h from every point of the first (a row near the rim may
// gain a point).
void check_fixed_point(const PointSet<3>& input, const Grid<3>& grid, double count_change = 0.01,
                       double far_share = 0.002) {
  ThreadPool pool(2);
  const double h = grid.spacing();
  const PointSet<3> first = resample_at(input, grid, pool);
  const PointSet<3> second = resample_at(first, grid, pool);
  const PointSet<3> third = resample_at(second, grid, pool);
  REQUIRE(first.size() > 200);
  const auto n1 = static_cast<double>(first.size());
  CHECK(std::abs(static_cast<double>(second.size()) - n1) <= count_change * n1);
  CHECK(std::abs(static_cast<double>(third.size()) - n1) <= count_change * n1);
  const AmlsSurface<3> first_surface = ready_surface(first, grid, pool);
  double past_rim = 0.0;
  for (std::size_t k = 0; k < third.size(); ++k)
    past_rim = std::max(past_rim, first_surface.rim().side(third.positions[k], third.normals[k]).value_or(0.0));
  CHECK(past_rim <= 0.5 * h);
  CHECK(static_cast<double>(farther_than(third, first, 0.75 * h)) <= far_share * static_cast<double>(third.size()));
}

}  // namespace

TEST_CASE("a point with neighbours on one side only is on the rim, its outward direction away from them") {
  const Vec<3> n = Vec<3>::UnitZ();
  std::vector<RimNeighbour<3>> half, whole, across;
  for (int k = 0; k < 24; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 24.0;
    const RimNeighbour<3> neighbour{Vec<3>(std::cos(a), std::sin(a), 0.01 * k), 2.0};
    whole.push_back(neighbour);
    if (neighbour.offset.x() < -1e-9) half.push_back(neighbour);
  }
  CHECK_FALSE(rim_outward<3>(n, whole).has_value());
  const std::optional<Vec<3>> out = rim_outward<3>(n, half);
  REQUIRE(out.has_value());
  CHECK(out->x() > 0.99);
  CHECK(std::abs(out->dot(n)) < 1e-12);
  // A point across the gap (farther than the nearest that decide the gap)
  // within its bridge closes it; beyond, it does not.
  across = half;
  across.push_back({Vec<3>(3.0, 0.2, 0.0), 3.5});
  CHECK_FALSE(rim_outward<3>(n, across).has_value());
  across.back().bridge = 2.5;
  CHECK(rim_outward<3>(n, across).has_value());
  // Too few neighbours to tell.
  const std::vector<RimNeighbour<3>> one{{Vec<3>(-1, 0, 0), 2.0}};
  CHECK_FALSE(rim_outward<3>(n, one).has_value());

  const Vec<2> n2(0.0, 1.0);
  const std::vector<RimNeighbour<2>> ahead{{Vec<2>(-0.5, 0.01), 2.0}, {Vec<2>(-1.0, 0.02), 2.0}};
  const std::optional<Vec<2>> end = rim_outward<2>(n2, ahead);
  REQUIRE(end.has_value());
  CHECK(end->x() > 0.99);
  const std::vector<RimNeighbour<2>> both{{Vec<2>(-1, 0), 2.0}, {Vec<2>(1, 0), 2.0}};
  CHECK_FALSE(rim_outward<2>(n2, both).has_value());
}

TEST_CASE("a point carried as rim stays on it across a neighbour that would bridge its gap, but not once surrounded") {
  const Vec<3> n = Vec<3>::UnitZ();
  std::vector<RimNeighbour<3>> half, whole;
  for (int k = 0; k < 24; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 24.0;
    const RimNeighbour<3> neighbour{Vec<3>(std::cos(a), std::sin(a), 0.01 * k), 3.5};
    if (neighbour.offset.x() < -1e-9) half.push_back(neighbour);
    if (k % 3 == 0) whole.push_back(neighbour);  // 45 degrees apart: surrounded
  }
  std::vector<RimNeighbour<3>> across = half;
  across.push_back({Vec<3>(3.0, 0.2, 0.0), 3.5});
  CHECK_FALSE(rim_outward<3>(n, across).has_value());
  const std::optional<Vec<3>> carried = rim_outward<3>(n, across, true);
  REQUIRE(carried.has_value());
  CHECK(carried->x() > 0.99);
  CHECK_FALSE(rim_outward<3>(n, whole, true).has_value());
}

TEST_CASE("the first row of new points inside a rim is not on the rim") {
  // Rim points 1.5 h apart on the line y = 0.5 h, the row half an h in, seen from its middle.
  const Vec<3> n = Vec<3>::UnitZ();
  std::vector<RimNeighbour<3>> row;
  for (const double x : {-2.25, -0.75, 0.75, 2.25}) row.push_back({Vec<3>(x, 0.5, 0.0), 4.5});
  for (const double x : {-2.0, -1.0, 1.0, 2.0}) row.push_back({Vec<3>(x, 0.0, 0.0), 4.5});
  for (const double x : {-1.5, -0.5, 0.5, 1.5}) row.push_back({Vec<3>(x, -1.0, 0.0), 4.5});
  CHECK_FALSE(rim_outward<3>(n, row).has_value());
}

TEST_CASE("the rim line cuts a sheet curling past it, but not a sheet facing the other way") {
  // One rim sample at the origin of the plane z = 0, normal +z, outward +x.
  SurfaceRim<3>::Samples samples;
  samples.ids = {0};
  samples.positions = {Vec<3>::Zero()};
  samples.outward = {Vec<3>::UnitX()};
  samples.normals = {Vec<3>::UnitZ()};
  samples.radii = {1.0};
  const SurfaceRim<3> rim(std::move(samples), Vec<3>(-2.0, -2.0, -2.0));
  const Vec<3> beyond(0.4, 0.0, -0.1);
  const auto turned = [](double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return Vec<3>(std::sin(a), 0.0, std::cos(a));
  };
  // A new point beyond the rim whose normal has turned 110 degrees (the
  // sheet curling down past the rim) is still beyond it ...
  const std::optional<double> curled = rim.side(beyond, turned(110.0));
  REQUIRE(curled.has_value());
  CHECK(*curled == doctest::Approx(0.4));
  // ... and one on a sheet facing the other way (a thin sheet's far side) is not the rim's.
  CHECK_FALSE(rim.side(beyond, turned(150.0)).has_value());
  CHECK_FALSE(rim.side(Vec<3>(3.0, 0.0, 0.0), Vec<3>::UnitZ()).has_value());
}

TEST_CASE("a crossing near the rim line stays where it gives back an old point, and a new one needs the full band") {
  // One carried rim point at the origin of the plane z = 0, normal +z,
  // outward +x, its support 3 h: G(x) = x.x near it.
  const double h = 0.1;
  CarriedRim<3> carried;
  SurfaceRim<3>::Samples samples;
  samples.ids = {0};
  samples.positions = {Vec<3>::Zero()};
  samples.outward = {Vec<3>::UnitX()};
  samples.normals = {Vec<3>::UnitZ()};
  samples.radii = {3.0 * h};
  carried.rim = SurfaceRim<3>(std::move(samples), Vec<3>(-1.0, -1.0, -1.0));
  const Vec<3> up = Vec<3>::UnitZ();
  int asked = 0;
  const auto inside = [&](double along, bool near_old_point) {
    return inside_rim(carried, h, Vec<3>(along * h, 0.5 * h, 0.0), up, [&] {
      ++asked;
      return near_old_point;
    });
  };
  // Well inside, or out of every rim point's reach: inside, and the old points are not asked about.
  CHECK(inside(-0.7, false));
  CHECK(inside(-2.0, false));
  CHECK(inside_rim(carried, h, Vec<3>(1.0, 1.0, 0.0), up, [&] {
    ++asked;
    return false;
  }));
  CHECK(asked == 0);
  // Within kRimBand h of the line: a new point is cut, one that gives back an old point stays.
  for (const double along : {-0.4, 0.0, 0.4}) {
    CHECK_FALSE(inside(along, false));
    CHECK(inside(along, true));
  }
  // Farther past the line than kRimBand h: cut, old point or not.
  CHECK_FALSE(inside(0.7, true));
  CHECK_FALSE(inside(1.5, true));
}

TEST_CASE("an open cap's rim samples are its outermost ring; a closed sphere has none") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> centre(0.5, 0.5, 0.4);
  const double radius = 0.3, cut = 0.12;
  const AmlsSurface<3> cap = ready_surface(sample_cap(centre, radius, cut, 0.8 * h), grid, pool);
  const auto& rim = cap.rim().samples();
  REQUIRE(rim.ids.size() > 20);
  const double rim_z = centre.z() + cut;
  for (std::size_t k = 0; k < rim.ids.size(); ++k) {
    CHECK(rim.positions[k].z() < rim_z + 1.5 * h);
    // Outward: down the sphere, away from the cap's top (-z along the tangent plane).
    const Vec<3> r = (rim.positions[k] - centre).normalized();
    const Vec<3> down_the_sphere = r * r.z() - Vec<3>::UnitZ();
    CHECK(rim.outward[k].dot(down_the_sphere.normalized()) > 0.7);
  }
  // Every sample within half an h of the cut is found.
  std::size_t lowest = 0;
  for (const Vec<3>& p : cap.points().positions) lowest += p.z() < rim_z + 0.4 * h ? 1 : 0;
  CHECK(rim.ids.size() >= lowest);

  const AmlsSurface<3> sphere = ready_surface(sample_sphere(centre, radius, 6000), grid, pool);
  CHECK(sphere.rim().empty());
}

TEST_CASE("resampling an open cap keeps its rim: no new point beyond it, and a resample of the resample changes nothing") {
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> centre(0.5, 0.5, 0.4);
  const double radius = 0.3, cut = 0.12;
  const PointSet<3> input = sample_cap(centre, radius, cut, 0.8 * h);
  double lowest_in = 1e9;
  for (const Vec<3>& p : input.positions) lowest_in = std::min(lowest_in, p.z());
  ThreadPool pool(2);
  const PointSet<3> out = resample_at(input, grid, pool);
  double lowest_out = 1e9;
  for (const Vec<3>& p : out.positions) lowest_out = std::min(lowest_out, p.z());
  // Down the sphere from the rim, z falls about as fast as arc length there.
  CHECK(lowest_out >= lowest_in - 0.1 * h);
  check_fixed_point(input, grid);
}

TEST_CASE("resampling a plane patch with a hole keeps the hole and the outer edge where they are") {
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const Vec<3> centre(0.5, 0.5, 0.503);
  const PointSet<3> input = sample_plane_patch(centre, 0.25, 0.08, 0.7 * h);
  ThreadPool pool(2);
  const PointSet<3> out = resample_at(input, grid, pool);
  double hole = 1e9, extent = 0.0;
  for (const Vec<3>& p : out.positions) {
    const Vec<3> d = p - centre;
    hole = std::min(hole, std::hypot(d.x(), d.y()));
    extent = std::max(extent, std::max(std::abs(d.x()), std::abs(d.y())));
  }
  CHECK(hole >= 0.08 - 0.1 * h);
  CHECK(extent <= 0.25 + 0.1 * h);
  // The lattice's slanted cut leaves a jagged rim, whose samples in the
  // notches the second resample finds inside the rim: its first resample
  // gains 1.4 % and moves 0.6 % of the points, the next ones nothing.
  check_fixed_point(input, grid, 0.015, 0.007);
}

TEST_CASE("a gap that the rim marks call a hole stays one, where the bridge test alone would fill it") {
  // A patch of the plane and a strip beside it, 3 h apart: a gap narrower
  // than the bridge (1.5 supports), which F spans. Unmarked, the facing
  // edges are bridged, no rim, and a resample fills the gap; marked as a
  // resample marks the rim it carries, they stay rim and the gap stays open.
  const Grid<3> grid = Grid<3>::unit(64);
  const double h = grid.spacing();
  const double z = 0.503, edge = 0.5, strip = edge + 3.0 * h;
  PointSet<3> unmarked;
  std::vector<std::uint8_t> facing;
  for (double x = 0.25; x <= strip + 2.0 * h; x += 0.7 * h) {
    if (x > edge && x < strip) continue;
    for (double y = 0.3; y <= 0.7; y += 0.7 * h) {
      unmarked.add(Vec<3>(x, y, z), Vec<3>::UnitZ());
      facing.push_back(x > edge - 0.7 * h && x < strip + 0.7 * h ? 1 : 0);
    }
  }
  PointSet<3> marked = unmarked;
  marked.rim = facing;
  ThreadPool pool(2);
  auto rim_at_the_gap = [&](const AmlsSurface<3>& surface) {
    std::size_t count = 0;
    for (const Vec<3>& p : surface.rim().samples().positions)
      count += p.x() > edge - h && p.x() < strip + h && p.y() > 0.3 + 2.0 * h && p.y() < 0.7 - 2.0 * h ? 1 : 0;
    return count;
  };
  // More than half an h into the gap, 2 h or more from its open ends (where
  // the rim turns the strip's corners, a resample of the resample puts a
  // point or two an h in from the strip).
  auto in_the_gap = [&](const PointSet<3>& points) {
    std::size_t count = 0;
    for (const Vec<3>& p : points.positions)
      count += p.x() > edge + 0.5 * h && p.x() < strip - 0.5 * h && p.y() > 0.3 + 2.0 * h && p.y() < 0.7 - 2.0 * h;
    return count;
  };
  CHECK(rim_at_the_gap(ready_surface(unmarked, grid, pool)) == 0);
  CHECK(in_the_gap(resample_at(unmarked, grid, pool)) > 20);
  const std::size_t marked_rows = static_cast<std::size_t>(std::count(facing.begin(), facing.end(), 1));
  const auto found = static_cast<double>(rim_at_the_gap(ready_surface(marked, grid, pool)));
  CHECK(found >= 0.8 * static_cast<double>(marked_rows));
  const PointSet<3> out = resample_at(marked, grid, pool);
  CHECK(in_the_gap(out) == 0);
  // The rim it carried is marked in its turn, and the next resample keeps the gap too.
  REQUIRE(out.rim.size() == out.size());
  CHECK(std::count(out.rim.begin(), out.rim.end(), 1) > 40);
  CHECK(in_the_gap(resample_at(out, grid, pool)) == 0);
}

TEST_CASE("a closed sphere is a fixed point of resampling too") {
  const Grid<3> grid = Grid<3>::unit(64);
  check_fixed_point(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 6000), grid);
}
