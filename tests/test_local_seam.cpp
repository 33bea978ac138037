// The seam of local resampling: the gap it leaves against a whole resample,
// the new points inside R against a whole resample's, and widened supports.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/kd_tree.hpp"
#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"
#include "core/resample/local_resampling.hpp"
#include "surface_fixtures.hpp"

using namespace amls;

namespace {

// The points of a whole resample of `points` (the paper's Resample over every point).
template <int D>
PointSet<D> whole_resample(const PointSet<D>& points, const Grid<D>& grid, const AmlsParameters& parameters,
                           ThreadPool& pool) {
  AmlsSurface<D> surface = test::ready_surface<D>(points, grid, pool, parameters);
  Resampler<D> resampler;
  resampler.update_function(surface, pool);
  return resampler.resample(surface, Variant::exact, pool);
}

// Resamples `points` where `flagged` says, with the local resampler; every other point's strain is just under the
// fraction of the limit the flagged cells grow into, as the kept points next to R are.
template <int D, typename Flagged>
PointSet<D> local_resample(PointSet<D> points, const Grid<D>& grid, const AmlsParameters& parameters, bool fill,
                           Flagged&& flagged, ThreadPool& pool) {
  LocalResampler<D> resampler(grid, parameters, Variant::exact);
  LocalResampleOptions options;
  options.fill_seam = fill;
  resampler.set_options(options);
  std::vector<float> strain(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    strain[i] = flagged(points.positions[i]) ? 1.0F : static_cast<float>(0.9 * options.grow_above * options.strain_limit);
  resampler.resample(points, strain, pool);
  return points;
}

// A resample of `shape`, turned off the grid's edges and stretched about its
// centre by `stretch`: a sampling as stretched as kept points get, or more.
template <int D>
PointSet<D> stretched_resample(const PointSet<D>& shape, const Vec<D>& center, double stretch, const Grid<D>& grid,
                               ThreadPool& pool) {
  PointSet<D> points = whole_resample<D>(shape, grid, AmlsParameters{}, pool);
  Mat<D> r;
  if constexpr (D == 2) {
    r = Eigen::Rotation2D<double>(0.3).toRotationMatrix();
  } else {
    r = Eigen::AngleAxisd(0.3, Vec<3>(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    points.positions[i] = center + stretch * (r * (points.positions[i] - center));
    points.normals[i] = r * points.normals[i];
  }
  return points;
}

// The largest distance from a probe to its nearest point, over the probes
// for which `counts` holds; in h.
template <int D, typename Counts>
double widest_gap(const std::vector<Vec<D>>& probes, const std::vector<Vec<D>>& points, double h, Counts&& counts) {
  KdTree<D> tree;
  tree.build(points);
  std::vector<std::uint32_t> ids;
  std::vector<double> squared;
  double widest = 0.0;
  for (const Vec<D>& p : probes) {
    if (!counts(p)) continue;
    tree.nearest(p, 1, ids, squared);
    widest = std::max(widest, std::sqrt(squared.front()) / h);
  }
  return widest;
}

// A shape (`sample(radius, points)`: a circle or sphere about `center`)
// resampled, stretched by 10 % (more than the kept points next to R are), and its half
// x < centre resampled locally: near the seam (R's edge lies within a region
// cell and Delta of the plane x = centre) the widest gap from the exact shape
// to the points is at most 10 % above a whole resample's, and the strip's
// new points are what keeps it there.
template <int D, typename Sample>
void check_seam_gaps(const Vec<D>& center, double radius, std::size_t points, std::size_t probes,
                     const Grid<D>& grid, Sample&& sample) {
  ThreadPool pool(2);
  const double h = grid.spacing();
  const double stretch = 1.1;
  const PointSet<D> stretched = stretched_resample<D>(sample(radius, points), center, stretch, grid, pool);
  const std::vector<Vec<D>> exact = sample(stretch * radius, probes).positions;
  auto flagged = [&](const Vec<D>& p) { return p.x() < center.x(); };
  const double band = 4.0 * h + 3.0 * h + 3.0 * h;  // a region cell, Delta, and a gap's own width
  auto near_seam = [&](const Vec<D>& p) { return std::abs(p.x() - center.x()) < band; };
  const double whole = widest_gap<D>(exact, whole_resample<D>(stretched, grid, AmlsParameters{}, pool).positions,
                                     h, [](const Vec<D>&) { return true; });
  auto at_seam = [&](bool fill) {
    return widest_gap<D>(exact, local_resample<D>(stretched, grid, AmlsParameters{}, fill, flagged, pool).positions,
                         h, near_seam);
  };
  const double filled = at_seam(true);
  const double unfilled = at_seam(false);
  MESSAGE("widest gap: whole resample " << whole << " h; at the seam " << filled << " h, without the strip "
                                        << unfilled << " h");
  CHECK(filled <= 1.1 * whole);
  CHECK(unfilled > filled);
}

}  // namespace

TEST_CASE("local seam, 2D: next to stretched kept points, no gap wider than a whole resample's") {
  const Vec<2> center(0.5, 0.5);
  check_seam_gaps<2>(center, 0.3, 400, 20000, Grid<2>::unit(128),
                     [&](double radius, std::size_t n) { return sample_circle(center, radius, n); });
}

TEST_CASE("local seam, 3D: next to stretched kept points, no gap wider than a whole resample's") {
  const Vec<3> center(0.5, 0.5, 0.5);
  check_seam_gaps<3>(center, 0.2, 4000, 100000, Grid<3>::unit(64),
                     [&](double radius, std::size_t n) { return sample_sphere(center, radius, n); });
}

namespace {

// The points of `points` where `inside` holds, sorted: to compare two sets.
template <typename Inside>
std::vector<Vec<3>> sorted_where(const PointSet<3>& points, Inside&& inside) {
  std::vector<Vec<3>> out;
  for (const Vec<3>& p : points.positions)
    if (inside(p)) out.push_back(p);
  std::sort(out.begin(), out.end(), [](const Vec<3>& a, const Vec<3>& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return out;
}

// Resamples the points where `flagged` holds locally and the whole surface:
// where `inside` holds (well inside R) the new points are the same.
template <typename Flagged, typename Inside>
void check_inside_region(const PointSet<3>& points, const Grid<3>& grid, const AmlsParameters& parameters,
                         Flagged&& flagged, Inside&& inside) {
  ThreadPool pool(2);
  const PointSet<3> whole = whole_resample<3>(points, grid, parameters, pool);
  const PointSet<3> local = local_resample<3>(points, grid, parameters, true, flagged, pool);
  const std::vector<Vec<3>> a = sorted_where(whole, inside);
  const std::vector<Vec<3>> b = sorted_where(local, inside);
  MESSAGE(a.size() << " new points well inside R");
  REQUIRE(a.size() > 100);
  CHECK(a == b);
}

// The points below z = `flag_below` resampled locally: below it by two region
// cells and the widest support the new points are a whole resample's.
void check_inside_region(const PointSet<3>& points, const Grid<3>& grid, const AmlsParameters& parameters,
                         double flag_below) {
  const double inside = flag_below - 8.0 * grid.spacing() - 4.0 * parameters.radius_factor * grid.spacing();
  check_inside_region(
      points, grid, parameters, [&](const Vec<3>& p) { return p.z() < flag_below; },
      [&](const Vec<3>& p) { return p.z() < inside; });
}

}  // namespace

TEST_CASE("local seam: inside R the new points are those of a whole resample of the same points") {
  const Vec<3> center(0.5, 0.5, 0.5);
  AmlsParameters parameters;
  // Widening on where nothing is sparse: every Delta_i is Delta, also for the
  // points at the support's rim (measured with their neighbours beyond it).
  for (const bool widen : {false, true}) {
    parameters.widen_support = widen;
    check_inside_region(sample_sphere(center, 0.3, 5000), Grid<3>::unit(64), parameters, center.z() + 0.1);
  }
}

TEST_CASE("local seam: with widened supports, a sparse half is covered and inside R the points are a whole resample's") {
  const PointSet<3> input = test::half_sparse_sphere(3000);
  const double h = sample_spacing<3>(sample_sphere(Vec<3>::Zero(), 1.0, 3000).positions).h;
  const Grid<3> grid(Vec<3>::Constant(-1.5), h);
  AmlsParameters parameters;
  parameters.widen_support = true;
  std::vector<Vec<3>> probes;
  for (const Vec<3>& p : sample_sphere(Vec<3>::Zero(), 1.0, 2000).positions)
    if (p.z() < -0.1) probes.push_back(p);
  ThreadPool pool(2);
  // Everything flagged (a start), then the sparse half and a band of the dense one.
  for (const double flag_below : {2.0, 0.2}) {
    const PointSet<3> out =
        local_resample<3>(input, grid, parameters, true, [&](const Vec<3>& p) { return p.z() < flag_below; }, pool);
    CHECK(test::probes_in_holes(out.positions, probes, 1.5 * h) == 0);
  }
  check_inside_region(input, grid, parameters, 0.2);
}

TEST_CASE("local seam: with widened supports, small regions at the sparse half's edge are a whole resample's inside") {
  // A few cells flagged: the support is grown for the widest Delta_i near
  // each region, not for the widest of the surface (a stray point far away
  // has the widest allowed, 4 Delta; near the regions the widest is 3.67
  // Delta). Inside the ball of flagged points, 2 h from any kept point (which
  // can claim a new point's vertex only within h sqrt(3)), the new points are
  // a whole resample's.
  PointSet<3> input = test::half_sparse_sphere(3000);
  input.add(Vec<3>(8.0, 0.0, 0.0), Vec<3>::UnitX());
  const double h = sample_spacing<3>(sample_sphere(Vec<3>::Zero(), 1.0, 3000).positions).h;
  const Grid<3> grid(Vec<3>::Constant(-1.5), h);
  AmlsParameters parameters;
  parameters.widen_support = true;
  const double radius = 10.0 * h;
  for (const Vec<3>& spot : {Vec<3>(1.0, 0.0, 0.15), Vec<3>(0.0, 1.0, -0.15)}) {
    const Vec<3> at = spot.normalized();
    check_inside_region(
        input, grid, parameters, [&](const Vec<3>& p) { return (p - at).norm() < radius; },
        [&](const Vec<3>& p) { return (p - at).norm() < radius - 2.0 * h; });
  }
}

TEST_CASE("local seam: widened supports far from sparse points: one Delta's support, a whole resample's points") {
  // The rings grow for the widest Delta_i near R: at the dense pole of the
  // half-sparse sphere (its sparse half about 23 region cells away), as far
  // as with one Delta for all. Its support widens nothing, so it takes the
  // path of one Delta while the whole surface takes the widened one: inside
  // the ball of flagged points the new points are still the whole's.
  const PointSet<3> input = test::half_sparse_sphere(30000);
  const double h = sample_spacing<3>(sample_sphere(Vec<3>::Zero(), 1.0, 30000).positions).h;
  const Grid<3> grid(Vec<3>::Constant(-1.5), h);
  const double radius = 10.0 * h;
  auto flagged = [&](const Vec<3>& p) { return (p - Vec<3>::UnitZ()).norm() < radius; };
  ThreadPool pool(2);
  auto support = [&](bool widen) {
    AmlsParameters parameters;
    parameters.widen_support = widen;
    LocalResampler<3> resampler(grid, parameters, Variant::exact);
    PointSet<3> points = input;
    std::vector<float> strain(points.size(), 0.0F);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (flagged(points.positions[i])) strain[i] = 1.0F;
    const LocalResampleStats stats = resampler.resample(points, strain, pool);
    REQUIRE(stats.inserted > 0);
    return stats.support;
  };
  const std::size_t widened = support(true);
  MESSAGE(widened << " points fitted");
  CHECK(widened == support(false));
  AmlsParameters parameters;
  parameters.widen_support = true;
  check_inside_region(input, grid, parameters, flagged,
                      [&](const Vec<3>& p) { return (p - Vec<3>::UnitZ()).norm() < radius - 2.0 * h; });
}
