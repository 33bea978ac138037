#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/deform/flow_deformation.hpp"
#include "core/deform/mls_lattice.hpp"
#include "core/deform/strain_lattice.hpp"
#include "core/geometry/shapes.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/run/flow_test.hpp"
#include "core/run/local_deforming_surface.hpp"

using namespace amls;

namespace {

// x -> centre + (1 + rate (t1 - t0)) (x - centre): a uniform scaling over the step.
template <int D>
class Scaling final : public Deformation<D> {
 public:
  explicit Scaling(double rate) : rate_(rate) {}
  void deform(PointSet<D>& points, double t0, double t1, ThreadPool&) const override {
    for (Vec<D>& p : points.positions)
      p = Vec<D>::Constant(0.5) + (1.0 + rate_ * (t1 - t0)) * (p - Vec<D>::Constant(0.5));
  }

 private:
  double rate_;
};

// x -> x + offset (t1 - t0).
template <int D>
class Translation final : public Deformation<D> {
 public:
  void deform(PointSet<D>& points, double t0, double t1, ThreadPool&) const override {
    for (Vec<D>& p : points.positions) p += (t1 - t0) * Vec<D>::Constant(0.013);
  }
};

}  // namespace

TEST_CASE("strain lattice: a translation strains by 0, a uniform scaling s by (s^2 - 1) sqrt(D) / 2") {
  ThreadPool pool(2);
  const PointSet<2> circle = sample_circle(Vec<2>(0.5, 0.5), 0.3, 2000);
  std::vector<float> strain;
  const StrainLatticeStats stats = add_step_strain<2>(Translation<2>(), 0.0, 1.0, circle.positions, 0.03, strain, pool);
  CHECK(stats.cells > 0);
  CHECK_FALSE(stats.fell_back);
  REQUIRE(strain.size() == circle.size());
  for (const float s : strain) REQUIRE(s < 1e-6F);
  strain.clear();
  add_step_strain<2>(Scaling<2>(0.02), 0.0, 0.5, circle.positions, 0.03, strain, pool);
  const double expected = 0.5 * (1.01 * 1.01 - 1.0) * std::sqrt(2.0);
  for (const float s : strain) REQUIRE(s == doctest::Approx(expected).epsilon(1e-5));
  // Steps add up.
  add_step_strain<2>(Scaling<2>(0.02), 0.0, 0.5, circle.positions, 0.03, strain, pool);
  for (const float s : strain) REQUIRE(s == doctest::Approx(2.0 * expected).epsilon(1e-5));
}

TEST_CASE("strain lattice: an MLS map's strain is the MLS lattice's, for any thread count") {
  // The same lattice (the points' box from its lowest corner, the same
  // spacing) over the same map: one strain for any deformation.
  const double h = 0.004;
  const Vec<3> c(0.5, 0.5, 0.5);
  std::vector<Vec<3>> from = {c - 0.3 * Vec<3>::UnitZ(), c + 0.3 * Vec<3>::UnitX(), c + 0.3 * Vec<3>::UnitY(),
                              c + 0.3 * Vec<3>::UnitZ()};
  std::vector<Vec<3>> to = from;
  to[3].z() += 3.0 * h;
  const MlsDeformation<3> map(from, to);
  const PointSet<3> start = sample_sphere(c, 0.3, 20000);
  ThreadPool pool(2), one(1);
  PointSet<3> mapped = start;
  std::vector<float> reference;
  apply_on_lattice(map, mapped, &reference, MlsLatticeOptions{8.0 * h, 0.0, 4, false}, pool);
  std::vector<float> strain, strain_one;
  add_step_strain<3>(map, 0.0, 1.0, start.positions, 8.0 * h, strain, pool);
  add_step_strain<3>(map, 0.0, 1.0, start.positions, 8.0 * h, strain_one, one);
  CHECK(strain == strain_one);
  REQUIRE(strain.size() == reference.size());
  float largest = 0.0F;
  for (std::size_t i = 0; i < strain.size(); ++i) {
    REQUIRE(strain[i] == doctest::Approx(reference[i]).epsilon(1e-5).scale(1e-6));
    largest = std::max(largest, strain[i]);
  }
  CHECK(largest > 1e-3F);
}

TEST_CASE("strain lattice: scattered points make the strain unknown (infinite)") {
  ThreadPool pool(1);
  std::vector<Vec<3>> scattered = {Vec<3>(0, 0, 0), Vec<3>(1, 1, 1), Vec<3>(0.5, 0.2, 0.9)};
  std::vector<float> strain;
  const StrainLatticeStats stats = add_step_strain<3>(Translation<3>(), 0.0, 1.0, scattered, 1e-3, strain, pool);
  CHECK(stats.fell_back);
  for (const float s : strain) CHECK(std::isinf(s));
  CHECK_THROWS_AS(add_step_strain<3>(Translation<3>(), 0.0, 1.0, scattered, 0.0, strain, pool), std::invalid_argument);
}

TEST_CASE("local loop with a velocity field: steps resample only where the flow strained, and no gap opens") {
  // The single vortex at 128^2: its first steps barely strain (t near 0 the
  // field is nearly rigid at the circle's scale), later ones stretch the curve.
  const Grid<2> grid = Grid<2>::unit(128);
  LocalDeformingSurface<2> local(grid, AmlsParameters{}, Variant::exact, 2,
                                 flow_resample_options(FlowTestConfig{}.strain_limit));
  local.set_points(sample_circle(Vec<2>(0.5, 0.75), 0.15, 1000));
  const LocalStepStats first = local.resample_all();
  CHECK(first.resample.inserted == local.points().size());
  const FlowDeformation<2> flow(std::make_shared<SingleVortex>(8.0), 1);
  std::size_t steps_resampling = 0, kept_steps = 0;
  for (int k = 0; k < 100; ++k) {
    const std::vector<Vec<2>> before = local.points().positions;
    const LocalStepStats s = local.step(flow, 0.01 * k, 0.01 * (k + 1));
    CHECK(s.strain_lattice.cells > 0);
    CHECK(s.timings.deform > 0.0);
    if (s.resample.flagged_cells > 0) {
      ++steps_resampling;
      CHECK(s.resample.replaced < s.points_before);  // local: not the whole curve
    } else {
      ++kept_steps;
      CHECK(s.points_after == s.points_before);
    }
  }
  MESSAGE(steps_resampling << " of 100 steps resampled somewhere");
  CHECK(steps_resampling > 0);
  CHECK(kept_steps > 0);
  // Every point surrounded by neighbours within the band `auto` keeps (no gap opened).
  ThreadPool pool(2);
  const SamplingQuality quality = sampling_quality(local.points(), grid.spacing(), 3.0, pool);
  MESSAGE("gap " << quality.gap << " h after 100 steps");
  CHECK(quality.gap <= 2.5);
}
