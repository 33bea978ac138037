// The start's resample (DeformingSurface::resample_start, and the local loop's
// LocalDeformingSurface::resample_start): a second pass where the samples are
// sparser than h, none on an even sampling, and the same points either way.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/run/local_deforming_surface.hpp"
#include "surface_fixtures.hpp"

using namespace amls;

namespace {

AmlsParameters widened() {
  AmlsParameters parameters;
  parameters.widen_support = true;
  return parameters;
}

// The positions in lexicographic order: the local loop lists its points in another order.
std::vector<Vec<3>> sorted(std::vector<Vec<3>> p) {
  std::sort(p.begin(), p.end(), [](const Vec<3>& a, const Vec<3>& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return p;
}

// At the dense half's h: 1 in 16 of the points (the sparse half's) widen.
const Grid<3> kGrid(Vec<3>::Constant(-1.5), 0.04);

}  // namespace

TEST_CASE("the start's resample of a half-sparse sphere makes a second pass, the one a resample after it makes") {
  const PointSet<3> shape = test::half_sparse_sphere(8000);
  DeformingSurface<3> start(kGrid, widened(), Variant::exact, 2);
  start.set_points(shape);
  const StepStats stats = start.resample_start();
  REQUIRE(stats.normals.widened > 0);
  CHECK(stats.points_before == shape.size());
  CHECK(stats.first_pass_points > 0);

  DeformingSurface<3> by_hand(kGrid, widened(), Variant::exact, 2);
  by_hand.set_points(shape);
  const StepStats first = by_hand.resample_only();
  CHECK(first.points_after == stats.first_pass_points);
  by_hand.resample_only();
  CHECK(by_hand.points().positions == start.points().positions);
  CHECK(by_hand.points().rim == start.points().rim);
  // The local loop starts from the same points.
  LocalDeformingSurface<3> local(kGrid, widened(), Variant::exact, 2);
  local.set_points(shape);
  const LocalStepStats local_stats = local.resample_start();
  CHECK(local_stats.first_pass_points == stats.first_pass_points);
  CHECK(sorted(local.points().positions) == sorted(start.points().positions));

  // Without the second pass: the first pass alone.
  DeformingSurface<3> one(kGrid, widened(), Variant::exact, 2);
  one.set_points(shape);
  CHECK(one.resample_start(false).first_pass_points == 0);
  CHECK(one.points().size() == stats.first_pass_points);
  CHECK(one.points().positions != start.points().positions);
}

TEST_CASE("the start's resample of an even sampling is one pass") {
  DeformingSurface<3> surface(kGrid, widened(), Variant::exact, 2);
  surface.set_points(sample_sphere(Vec<3>::Zero(), 1.0, 8000));
  const StepStats stats = surface.resample_start();
  CHECK(stats.normals.widened * 100 < stats.points_before);
  CHECK(stats.first_pass_points == 0);
}
