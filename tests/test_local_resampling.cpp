#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/run/drag_bench.hpp"
#include "core/run/local_deforming_surface.hpp"
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
  // A new point may come as close to a kept one as the resampler puts two of
  // its own at neighbouring vertices (h / sqrt(2)), and no closer.
  CHECK(*seam_lo >= std::min(*in_lo, std::sqrt(0.5)));
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

TEST_CASE("local resampling: flagged cells grow into the strained cells next to them, not across unstrained ones") {
  const Grid<2> grid = Grid<2>::unit(64);
  const Vec<2> center(0.5, 0.5);
  ThreadPool pool(1);
  const PointSet<2> circle = sample_circle(center, 0.3, 400);
  const double limit = LocalResampleOptions{}.strain_limit;
  // By angle: over the limit near 0, past 0.7 of it on to 0.8 rad (joined to
  // the flagged cells), under it on to 1.6 rad (a gap of four region cells),
  // past 0.7 again on to 2 rad (not joined), under it elsewhere.
  auto angle_of = [&](const Vec<2>& p) { return std::atan2(p.y() - center.y(), p.x() - center.x()); };
  std::vector<float> strain(circle.size());
  for (std::size_t i = 0; i < circle.size(); ++i) {
    const double a = angle_of(circle.positions[i]);
    const bool warm = (a > 0.05 && a <= 0.8) || (a >= 1.6 && a <= 2.0);
    strain[i] = static_cast<float>((a >= 0.0 && a <= 0.05) ? 2.0 * limit : warm ? 0.8 * limit : 0.1 * limit);
  }
  auto kept = [&](const PointSet<2>& out, double from, double to) {
    std::size_t in_range = 0, unmoved = 0;
    for (const Vec<2>& p : circle.positions) {
      const double a = angle_of(p);
      if (a < from || a > to) continue;
      ++in_range;
      if (std::find(out.positions.begin(), out.positions.end(), p) != out.positions.end()) ++unmoved;
    }
    REQUIRE(in_range > 0);
    return static_cast<double>(unmoved) / static_cast<double>(in_range);
  };
  auto run = [&](double grow_above) {
    LocalResampler<2> resampler(grid, AmlsParameters{}, Variant::exact);
    LocalResampleOptions options;
    options.grow_above = grow_above;
    resampler.set_options(options);
    PointSet<2> points = circle;
    std::vector<float> s = strain;
    const LocalResampleStats stats = resampler.resample(points, s, pool);
    return std::pair{stats, points};
  };
  const auto [grown, grown_points] = run(LocalResampleOptions{}.grow_above);
  const auto [alone, alone_points] = run(kNoGrowth);
  CHECK(grown.flagged_cells > alone.flagged_cells);
  // The joined strained arc is resampled with the flagged cells; without growth its far part is kept.
  CHECK(kept(grown_points, 0.5, 0.8) == 0.0);
  CHECK(kept(alone_points, 0.5, 0.8) == 1.0);
  // The arc past the gap is kept either way, as is the unstrained rest.
  CHECK(kept(grown_points, 1.6, 2.0) == 1.0);
  CHECK(kept(grown_points, 2.5, 3.0) == 1.0);
}

TEST_CASE("local resampling: no strained point, nothing changes") {
  const Grid<2> grid = Grid<2>::unit(64);
  ThreadPool pool(1);
  LocalResampler<2> resampler(grid, AmlsParameters{}, Variant::exact);
  PointSet<2> points = sample_circle(Vec<2>(0.5, 0.5), 0.3, 200);
  const PointSet<2> before = points;
  // Under the limit, and past the fraction the flagged cells grow into: none is flagged, none grown into.
  std::vector<float> strain(points.size(), static_cast<float>(0.9 * resampler.options().strain_limit));
  const LocalResampleStats stats = resampler.resample(points, strain, pool);
  CHECK(stats.flagged_cells == 0);
  CHECK(points.positions == before.positions);
  std::vector<float> wrong(3, 0.0F);
  CHECK_THROWS_AS(resampler.resample(points, wrong, pool), std::invalid_argument);
}

namespace {

// The drag benchmark's handles (core/run/drag_bench.hpp) on a sphere of radius 0.3.
MlsDeformation<3> drag_step(double pull, std::size_t step) {
  const Vec<3> c(0.5, 0.5, 0.5);
  return MlsDeformation<3>(drag_handles(c, 0.3, pull, step), drag_handles(c, 0.3, pull, step + 1));
}

}  // namespace

TEST_CASE("local drag: the points follow the whole drag's map from their rest positions, its error does not add up") {
  const double h = 0.3 * std::sqrt(0.83 * 4.0 * 3.14159265 / 8000.0);
  LocalDeformingSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{}, Variant::exact, 2);
  surface.set_points(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 8000));
  surface.resample_all();
  const PointSet<3> start = surface.points();
  std::vector<double> errors;
  const double pull = 0.1 * h;  // mild on a sphere only 25 h wide: nothing is resampled
  for (std::size_t k = 0; k < 12; ++k) {
    const LocalStepStats stats = surface.step(drag_step(pull, k));
    REQUIRE(stats.resample.flagged_cells == 0);
    CHECK(surface.rest_handles() == drag_step(pull, 0).from());
    PointSet<3> exact = start;
    MlsDeformation<3>(drag_step(pull, 0).from(), drag_step(pull, k).to()).apply(exact, surface.pool());
    REQUIRE(exact.size() == surface.points().size());
    double worst = 0.0;
    for (std::size_t i = 0; i < exact.size(); ++i)
      worst = std::max(worst, (exact.positions[i] - surface.points().positions[i]).norm() / h);
    errors.push_back(worst);
  }
  MESSAGE("largest distance to the exact map of the drag so far, per step (h): " << errors.front() << " ... "
                                                                                 << errors.back());
  // The lattice's tolerance (0.01 h at the cells' centres, up to about 3 times that between them), at every step.
  CHECK(*std::max_element(errors.begin(), errors.end()) < 0.03);
  CHECK(errors.back() > 0.0);  // interpolated, not exact
  // Handles that are not where the last step left them: a new drag, from where they are now.
  std::vector<Vec<3>> moved = drag_step(pull, 11).to(), target = moved;
  moved[1].x() += h;
  target[1].x() += 1.1 * h;
  const LocalStepStats stats = surface.step(MlsDeformation<3>(moved, target));
  REQUIRE(stats.resample.flagged_cells == 0);
  CHECK(surface.rest_handles() == moved);
}

TEST_CASE("local drag: its end maps the points exactly, and the drag's next step runs as if it had not") {
  const double h = 0.3 * std::sqrt(0.83 * 4.0 * 3.14159265 / 8000.0);
  auto make = [&] {
    auto surface = std::make_unique<LocalDeformingSurface<3>>(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{},
                                                              Variant::exact, 2);
    surface->set_points(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 8000));
    surface->resample_all();
    return surface;
  };
  const auto paused = make(), straight = make();
  const PointSet<3> start = paused->points();
  CHECK_FALSE(paused->map_exactly());  // at rest: nothing interpolated
  const double pull = 0.1 * h;
  for (std::size_t k = 0; k < 3; ++k)
    for (LocalDeformingSurface<3>* s : {paused.get(), straight.get()})
      REQUIRE(s->step(drag_step(pull, k)).resample.flagged_cells == 0);
  REQUIRE(paused->points().positions == straight->points().positions);
  REQUIRE(paused->map_exactly());
  CHECK_FALSE(paused->map_exactly());  // exact already
  PointSet<3> exact = start;
  MlsDeformation<3> whole(drag_step(pull, 0).from(), drag_step(pull, 2).to());
  whole.use_polar_iteration(true);
  whole.apply(exact, paused->pool());
  CHECK(paused->points().positions == exact.positions);
  CHECK(paused->points().normals == exact.normals);
  CHECK(paused->points().positions != straight->points().positions);  // the lattice's were interpolated
  CHECK(paused->rest_handles() == straight->rest_handles());
  for (LocalDeformingSurface<3>* s : {paused.get(), straight.get()})
    REQUIRE(s->step(drag_step(pull, 3)).resample.flagged_cells == 0);
  CHECK(paused->points().positions == straight->points().positions);
  CHECK(paused->strain() == straight->strain());
}

TEST_CASE("local drag: a saved state within a drag holds no copy of the points, and restores them exactly") {
  const double h = 0.3 * std::sqrt(0.83 * 4.0 * 3.14159265 / 8000.0);
  LocalDeformingSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{}, Variant::exact, 2);
  surface.set_points(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 8000));
  surface.resample_all();
  // At rest the points are not a map of anything: copied.
  CHECK(surface.save().points.has_value());
  const double pull = 0.1 * h;
  for (std::size_t k = 0; k < 2; ++k) REQUIRE(surface.step(drag_step(pull, k)).resample.flagged_cells == 0);
  const PointSet<3> before = surface.points();
  const std::vector<float> strain_before = surface.strain();
  LocalDeformingSurface<3>::Saved saved = surface.save();
  CHECK_FALSE(saved.points.has_value());
  // A step to undo, then another drag (a new rest state), then back.
  const PointSet<3> after_step = [&] {
    REQUIRE(surface.step(drag_step(pull, 2)).resample.flagged_cells == 0);
    return surface.points();
  }();
  std::vector<Vec<3>> moved = drag_step(pull, 3).from(), target = moved;
  target[1].x() += h;
  REQUIRE(surface.step(MlsDeformation<3>(moved, target)).resample.flagged_cells == 0);
  surface.restore(std::move(saved));
  CHECK(surface.points().positions == before.positions);
  CHECK(surface.points().normals == before.normals);
  CHECK(surface.strain() == strain_before);
  // The drag goes on as if the steps in between had not run.
  REQUIRE(surface.step(drag_step(pull, 2)).resample.flagged_cells == 0);
  CHECK(surface.points().positions == after_step.positions);
  // Mapped exactly (a drag's end), the points are copied again.
  REQUIRE(surface.map_exactly());
  CHECK(surface.save().points.has_value());
}

TEST_CASE("local drag: a step that resamples maps every point exactly and starts a new rest state") {
  const double h = 0.3 * std::sqrt(0.83 * 4.0 * 3.14159265 / 6000.0);
  LocalDeformingSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{}, Variant::exact, 2);
  surface.set_points(sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 6000));
  surface.resample_all();
  const PointSet<3> start = surface.points();
  const double pull = 6.0 * h;  // strains the top past the limit in one step
  const LocalStepStats stats = surface.step(drag_step(pull, 0));
  REQUIRE(stats.resample.replaced > 0);
  CHECK(surface.rest_handles() == drag_step(pull, 0).to());
  // The kept points come first, in their order: each is the exact map of a start point, to 1e-9 relative.
  PointSet<3> exact = start;
  drag_step(pull, 0).apply(exact, surface.pool());
  const std::size_t kept = surface.points().size() - stats.resample.inserted - stats.resample.filled_at_seam;
  std::size_t matched = 0;
  for (std::size_t i = 0, j = 0; i < kept && j < exact.size(); ++j) {
    const Vec<3>& p = surface.points().positions[i];
    if ((p - exact.positions[j]).norm() > 1e-9 * exact.positions[j].norm()) continue;
    ++matched;
    ++i;
  }
  CHECK(matched == kept);
}
