#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/surface/metrics.hpp"
#include "surface_fixtures.hpp"

using namespace amls;

namespace {

template <int D>
PointSet<D> rotated(PointSet<D> points, const Vec<D>& center, double angle) {
  Mat<D> r;
  if constexpr (D == 2) {
    r = Eigen::Rotation2D<double>(angle).toRotationMatrix();
  } else {
    r = Eigen::AngleAxisd(angle, Vec<3>(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    points.positions[i] = center + r * (points.positions[i] - center);
    points.normals[i] = r * points.normals[i];
  }
  return points;
}

template <int D>
struct SeamCase {
  std::vector<double> inside;  // nearest-neighbour spacing (h) of points more than 3 h from the other kind
  std::vector<double> seam;    // ... of points within 2 h of a point of the other kind
  std::size_t kept = 0;
  std::size_t kept_unchanged = 0;
  PointSet<D> out;
  LocalResampleStats stats;
};

// A whole resample of the shape, rotated about its centre (the kept points
// leave the grid's edges, the shape stays exact), then a local resample of the
// half x < center.x.
template <int D>
SeamCase<D> seam_case(const PointSet<D>& shape, const Vec<D>& center, const Grid<D>& grid) {
  ThreadPool pool(2);
  LocalResampler<D> resampler(grid, AmlsParameters{}, Variant::exact);
  PointSet<D> points = shape;
  std::vector<float> strain(points.size(), std::numeric_limits<float>::infinity());
  resampler.resample(points, strain, pool);
  REQUIRE(std::all_of(strain.begin(), strain.end(), [](float s) { return s == 0.0F; }));
  points = rotated(points, center, 0.3);
  const PointSet<D> before = points;
  for (std::size_t i = 0; i < points.size(); ++i) strain[i] = points.positions[i].x() < center.x() ? 1.0F : 0.0F;
  SeamCase<D> c;
  c.stats = resampler.resample(points, strain, pool);
  c.out = points;
  const double h = grid.spacing();
  // Kept points come first, unchanged; new ones (strain 0 and not in `before`) after.
  std::vector<bool> fresh(points.size(), true);
  for (std::size_t i = 0, j = 0; i < points.size() && j < before.size(); ++i) {
    while (j < before.size() && before.positions[j] != points.positions[i]) ++j;
    if (j == before.size()) break;
    fresh[i] = false;
    ++c.kept;
    if (before.normals[j] == points.normals[i]) ++c.kept_unchanged;
  }
  const std::vector<double> spacing = nearest_neighbour_spacing_per_point(points, h);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double other = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < points.size(); ++j)
      if (fresh[j] != fresh[i]) other = std::min(other, (points.positions[j] - points.positions[i]).norm() / h);
    if (other <= 2.0) c.seam.push_back(spacing[i]);
    if (other > 3.0) c.inside.push_back(spacing[i]);
  }
  return c;
}

template <int D>
void check_seam(const SeamCase<D>& c) {
  REQUIRE(c.stats.inserted > 0);
  REQUIRE(c.stats.replaced > 0);
  CHECK(c.kept_unchanged == c.kept);
  INFO("points " << c.out.size() << ", kept " << c.kept << ", seam " << c.seam.size() << ", inside "
                 << c.inside.size());
  REQUIRE(c.seam.size() >= 4);  // a point on each side of each seam, at least
  REQUIRE(c.inside.size() > 4);
  const auto [in_lo, in_hi] = std::minmax_element(c.inside.begin(), c.inside.end());
  const auto [seam_lo, seam_hi] = std::minmax_element(c.seam.begin(), c.seam.end());
  MESSAGE("spacing inside [" << *in_lo << ", " << *in_hi << "] h, across the seam [" << *seam_lo << ", " << *seam_hi
                             << "] h; " << c.stats.dropped_at_seam << " crossings dropped at the seam");
  CHECK(*seam_lo >= *in_lo);
  CHECK(*seam_hi <= *in_hi);
}

}  // namespace

TEST_CASE(
    "local resampling, 2D: kept points unchanged, new points on the circle, spacing across the seam within the band "
    "inside") {
  const Vec<2> center(0.5, 0.5);
  const Grid<2> grid = Grid<2>::unit(128);
  const SeamCase<2> c = seam_case<2>(sample_circle(center, 0.3, 400), center, grid);
  check_seam(c);
  for (const Vec<2>& p : c.out.positions) CHECK(std::abs((p - center).norm() - 0.3) < 1e-3 * grid.spacing());
  CHECK(test::widest_circle_gap(c.out.positions, center, 0.3) < 2.0 * grid.spacing());
}

TEST_CASE("local resampling, 3D: kept points unchanged, no hole, spacing across the seam within the band inside") {
  const Vec<3> center(0.5, 0.5, 0.5);
  const Grid<3> grid = Grid<3>::unit(64);
  const SeamCase<3> c = seam_case<3>(sample_sphere(center, 0.2, 4000), center, grid);
  check_seam(c);
  const PointSet<3> probes = sample_sphere(center, 0.2, 20000);
  CHECK(nearest_distance_stats<3>(probes.positions, c.out.positions, grid.spacing()).max < 1.25);
}

TEST_CASE("local resampling: no strained point, nothing changes") {
  const Grid<2> grid = Grid<2>::unit(64);
  ThreadPool pool(1);
  LocalResampler<2> resampler(grid, AmlsParameters{}, Variant::exact);
  PointSet<2> points = sample_circle(Vec<2>(0.5, 0.5), 0.3, 200);
  const PointSet<2> before = points;
  std::vector<float> strain(points.size(), 0.1F);
  const LocalResampleStats stats = resampler.resample(points, strain, pool);
  CHECK(stats.flagged_cells == 0);
  CHECK(points.positions == before.positions);
  std::vector<float> wrong(3, 0.0F);
  CHECK_THROWS_AS(resampler.resample(points, wrong, pool), std::invalid_argument);
}
