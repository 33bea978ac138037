#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/resample/resampler.hpp"
#include "core/resample/segment_root.hpp"
#include "core/resample/sheet_edge.hpp"
#include "core/geometry/shapes.hpp"
#include "resampling_checks.hpp"
#include "surface_fixtures.hpp"

using namespace amls;
using amls::test::nearest_neighbour_distances;
using amls::test::ready_surface;

namespace {

template <int D>
PointSet<D> resample_once(const AmlsSurface<D>& surface, Variant variant, ThreadPool& pool) {
  Resampler<D> resampler;
  resampler.update_function(surface, pool);
  return resampler.resample(surface, variant, pool);
}

// HAVECLOSEPOINT by brute force: every edge between two vertices with
// defined values of opposite signs, its root located from whole evaluations
// of F, and at each vertex the crossing nearest to it.
std::vector<Vec<2>> nearest_crossings_by_brute_force(const AmlsSurface<2>& surface, const Resampler<2>& resampler) {
  const Grid<2> grid = surface.grid();
  const double h = grid.spacing();
  std::map<std::pair<std::int64_t, std::int64_t>, std::pair<double, Vec<2>>> nearest;  // vertex -> distance, point
  const auto cells = static_cast<std::int64_t>(std::lround(1.0 / h));  // a unit grid: the shapes lie inside
  for (std::int64_t y = 0; y <= cells; ++y)
    for (std::int64_t x = 0; x <= cells; ++x)
      for (int axis = 0; axis < 2; ++axis) {
        const IVec<2> from(x, y);
        const IVec<2> to = from + IVec<2>::Unit(axis);
        const Evaluation<2>* f0 = resampler.vertex_value(from);
        const Evaluation<2>* f1 = resampler.vertex_value(to);
        if (!f0 || !f1 || !f0->defined || !f1->defined || (f0->value >= 0.0) == (f1->value >= 0.0)) continue;
        const Vec<2> start = grid.vertex_position(from);
        const Vec<2> step = h * Vec<2>::Unit(axis);
        const SegmentRoot<2> root =
            locate_segment_root<2>([&](const Vec<2>& p) { return surface.evaluate(p); }, start, step, *f0, *f1,
                                   estimate_segment_root<2>(*f0, *f1, step), axis);
        const IVec<2> end = root.t < 0.5 ? from : to;
        const double distance = std::min(root.t, 1.0 - root.t);
        auto [it, inserted] = nearest.try_emplace({end[0], end[1]}, distance, start + root.t * step);
        if (!inserted && distance < it->second.first) it->second = {distance, start + root.t * step};
      }
  std::vector<Vec<2>> points;
  for (const auto& [vertex, kept] : nearest) points.push_back(kept.second);
  return points;
}

bool lexicographic_less(const Vec<2>& a, const Vec<2>& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); }

}  // namespace

TEST_CASE("a sign change that is a jump of F, not a zero, is located as a jump") {
  // F as the orientation filter makes it between two sheets' fits: -0.4 h on
  // one side of where the nearest point switches sheets, +0.6 h on the other.
  const double h = 0.01;
  const Vec<2> start(0.0, 0.0);
  const Vec<2> step(h, 0.0);
  auto value_at = [&](double x, bool smooth) {
    Evaluation<2> e;
    e.defined = true;
    e.value = smooth ? x - 0.37 * h : (x < 0.37 * h ? -0.4 * h : 0.6 * h);
    e.gradient = smooth ? Vec<2>(1.0, 0.0) : Vec<2>::Zero();
    e.mean_normal = Vec<2>(1.0, 0.0);
    return e;
  };
  for (const bool smooth : {false, true}) {
    auto evaluate = [&](const Vec<2>& y) { return value_at(y[0], smooth); };
    const Evaluation<2> f0 = value_at(0.0, smooth);
    const Evaluation<2> f1 = value_at(h, smooth);
    const SegmentRoot<2> root =
        locate_segment_root<2>(evaluate, start, step, f0, f1, estimate_segment_root<2>(f0, f1, step), 0);
    CHECK(root.jump == !smooth);
    // A jump is given as its bracket's nearer end when recognised: within a
    // hundredth of the edge (core/math/root_finding.hpp's kJumpFactor).
    CHECK(std::abs(root.t - 0.37) < (smooth ? 1e-9 : 1e-2));
  }
}

TEST_CASE("a new point is past a sheet's edge only where the old points all lie to one side, none within h, none sparse") {
  // A sheet in the plane z = 0 ending at x = 0, sampled every h, and its
  // other side (normals down) 0.4 h below: a point a row and a half past
  // the edge, inside and at the edge.
  const double h = 0.01;
  Neighbourhood<3> sheet;
  for (int i = -6; i <= 0; ++i)
    for (int j = -6; j <= 6; ++j)
      for (const double z : {0.0, -0.4 * h}) {
        sheet.positions.push_back(Vec<3>(i * h, j * h, z));
        sheet.normals.push_back(z == 0.0 ? Vec<3>::UnitZ() : Vec<3>(-Vec<3>::UnitZ()));
      }
  const Vec<3> up = Vec<3>::UnitZ();
  CHECK(beyond_sheet_edge<3>(sheet, Vec<3>(1.5 * h, 0.3 * h, 0.0), up, h, 3.0 * h));
  CHECK_FALSE(beyond_sheet_edge<3>(sheet, Vec<3>(-3.0 * h, 0.3 * h, 0.0), up, h, 3.0 * h));  // surrounded
  CHECK_FALSE(beyond_sheet_edge<3>(sheet, Vec<3>(0.5 * h, 0.3 * h, 0.0), up, h, 3.0 * h));   // within h of the edge's points
  CHECK_FALSE(beyond_sheet_edge<3>(Neighbourhood<3>{}, Vec<3>::Zero(), up, h, 3.0 * h));  // no old point: nothing to judge
  // A support widened among them: the points are sparser than h, no edge.
  Neighbourhood<3> sparse = sheet;
  const double radius = 3.0 * h;
  sparse.inverse_r2.assign(sparse.positions.size(), 1.0 / (radius * radius));
  CHECK(beyond_sheet_edge<3>(sparse, Vec<3>(1.5 * h, 0.3 * h, 0.0), up, h, radius));
  sparse.inverse_r2.front() = 1.0 / (4.0 * radius * radius);
  CHECK_FALSE(beyond_sheet_edge<3>(sparse, Vec<3>(1.5 * h, 0.3 * h, 0.0), up, h, radius));
  // One side alone (a sparse input resampled finely, or an open surface,
  // whose rims have their own rule): no sheet's edge.
  for (Vec<3>& n : sheet.normals) n = Vec<3>::UnitZ();
  CHECK_FALSE(beyond_sheet_edge<3>(sheet, Vec<3>(1.5 * h, 0.3 * h, 0.0), up, h, 3.0 * h));
}

TEST_CASE("locating only the crossings that may win HAVECLOSEPOINT keeps what locating every crossing keeps") {
  // The resampler judges losers on the root finder's first guesses; off-circle
  // shapes make those guesses inexact, so a wrong judgement would show.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  const double h = grid.spacing();
  for (PointSet<2> shape : {sample_ellipse(Vec<2>(0.5, 0.5), Vec<2>(0.31, 0.11), 0.8 * h),
                            sample_rounded_box(Vec<2>(0.47, 0.52), Vec<2>(0.2, 0.13), 0.04, 0.9 * h)}) {
    // Rippled across the curve, as a deformed point set is, so that F bends
    // between vertices and the first guesses miss by more.
    for (std::size_t i = 0; i < shape.size(); ++i)
      shape.positions[i] += 0.3 * h * std::sin(0.9 * static_cast<double>(i)) * shape.normals[i];
    const auto surface = ready_surface(shape, grid, pool);
    Resampler<2> resampler;
    resampler.update_function(surface, pool);
    std::vector<Vec<2>> kept = resampler.resample(surface, Variant::exact, pool).positions;
    std::vector<Vec<2>> expected = nearest_crossings_by_brute_force(surface, resampler);
    // Fewer roots located than there are crossings: losers were dropped.
    CHECK(resampler.stats().located < resampler.stats().crossings);
    REQUIRE(kept.size() == expected.size());
    std::sort(kept.begin(), kept.end(), lexicographic_less);
    std::sort(expected.begin(), expected.end(), lexicographic_less);
    double worst = 0.0;
    for (std::size_t i = 0; i < kept.size(); ++i) worst = std::max(worst, (kept[i] - expected[i]).norm());
    CHECK(worst < 1e-9 * h);
  }
}

TEST_CASE("exact resampling of a circle puts every new point on F = 0, well spaced, with no gap wider than 2 h") {
  ThreadPool pool(2);
  const auto surface = test::circle_surface(pool);
  const double h = surface.grid().spacing();
  const PointSet<2> out = resample_once(surface, Variant::exact, pool);
  test::check_resampled_circle(surface, out);
  const auto nn = nearest_neighbour_distances<2>(out.positions);
  CHECK(*std::min_element(nn.begin(), nn.end()) > 0.25 * h);
  CHECK(*std::max_element(nn.begin(), nn.end()) < 2.0 * h);
}

TEST_CASE("HAVECLOSEPOINT keeps the crossing nearest each vertex: spacings right after a resample lie in [0.5 h, 1.5 h]") {
  // Circles of many radii and sub-cell offsets meet the grid's vertices at
  // every angle; the walk-order rule of the paper left gaps up to 1.6 h here.
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(64);
  const double h = grid.spacing();
  double smallest = 1e300;
  double largest = 0.0;
  for (int k = 0; k < 12; ++k) {
    const Vec<2> center(0.5 + 0.37 * h * k / 12.0, 0.5 + 0.71 * h * ((k * 5) % 12) / 12.0);
    const double radius = 0.12 + 0.02 * k;
    const auto surface = ready_surface(sample_circle(center, radius, 400), grid, pool);
    const auto nn = nearest_neighbour_distances<2>(resample_once(surface, Variant::exact, pool).positions);
    smallest = std::min(smallest, *std::min_element(nn.begin(), nn.end()));
    largest = std::max(largest, *std::max_element(nn.begin(), nn.end()));
  }
  CHECK(smallest >= 0.5 * h);
  CHECK(largest <= 1.5 * h);
}

TEST_CASE("exact resampling of a sphere puts every new point on the sphere, well spaced, with no hole") {
  ThreadPool pool(2);
  const auto surface = test::sphere_surface(pool);
  const double h = surface.grid().spacing();
  const PointSet<3> out = resample_once(surface, Variant::exact, pool);
  test::check_resampled_sphere(surface, out);
  const auto nn = nearest_neighbour_distances<3>(out.positions);
  CHECK(*std::min_element(nn.begin(), nn.end()) > 0.25 * h);
  CHECK(*std::max_element(nn.begin(), nn.end()) < 2.0 * h);
}

TEST_CASE("interpolated resampling stays within a small fraction of h of a circle") {
  ThreadPool pool(1);
  const Grid<2> grid = Grid<2>::unit(128);
  const Vec<2> center(0.5, 0.75);
  const auto surface = ready_surface(sample_circle(center, 0.15, 150), grid, pool);
  const PointSet<2> out = resample_once(surface, Variant::interpolated, pool);
  REQUIRE(out.size() > 100);
  for (const auto& q : out.positions) CHECK(std::abs((q - center).norm() - 0.15) < 0.05 * grid.spacing());
}

TEST_CASE("resampling gives the same points for any thread count") {
  const Grid<2> grid = Grid<2>::unit(128);
  ThreadPool one(1), three(3);
  const auto a = resample_once(ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.2, 97), grid, one), Variant::exact, one);
  const auto b = resample_once(ready_surface(sample_circle(Vec<2>(0.5, 0.5), 0.2, 97), grid, three), Variant::exact, three);
  CHECK(a.positions == b.positions);
  CHECK(a.normals == b.normals);
}

TEST_CASE("a surface through grid vertices gives exactly one point per vertex") {
  // F is exactly 0 at the line's vertices. A zero counts as positive, so each
  // vertex on the line is the upper end of one crossing edge (from the negative
  // vertex below) and gets one point.
  ThreadPool pool(1);
  const auto surface = test::line_through_vertices(pool);
  test::check_one_point_per_vertex(resample_once(surface, Variant::exact, pool), surface.grid().spacing());
}

TEST_CASE("memory follows the surface: a small sphere on a 2048^3 grid touches few vertices") {
  ThreadPool pool(2);
  const Grid<3> grid = Grid<3>::unit(2048);
  const auto surface = ready_surface(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.01, 5000), grid, pool);
  Resampler<3> resampler;
  resampler.update_function(surface, pool);
  const PointSet<3> out = resampler.resample(surface, Variant::exact, pool);
  CHECK(out.size() > 3000);
  // About 7 vertices per point, in bricks of 64: a few hundred thousand slots
  // at most, i.e. a few tens of MiB, against 8.6e9 vertices in the grid.
  CHECK(resampler.stats().vertices < 20 * surface.points().size());
  CHECK(resampler.vertex_slots() < 500000);
}
