#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <cmath>
#include <vector>

#include "core/deform/mls_lattice.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;

namespace {

// A sphere of radius 0.3 dragged at its top by `pull`, three handles fixed (the drag benchmark's set-up).
MlsDeformation<3> drag(double pull) {
  const Vec<3> c(0.5, 0.5, 0.5);
  const double r = 0.3;
  std::vector<Vec<3>> from = {c - r * Vec<3>::UnitZ(), c + r * Vec<3>::UnitX(), c + r * Vec<3>::UnitY(),
                              c + r * Vec<3>::UnitZ()};
  std::vector<Vec<3>> to = from;
  to[3].z() += pull;
  return MlsDeformation<3>(from, to);
}

// The drag's sphere at rest, and lattices of 8 h over it.
struct RestSphere {
  double h = 0.004;
  PointSet<3> rest = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 20000);
  ThreadPool pool{2};

  MlsLatticeOptions options(double tolerance_in_h) const { return {8.0 * h, tolerance_in_h * h, 4, true}; }
  MlsRestLattice<3> lattice(double tolerance_in_h) { return MlsRestLattice<3>(rest, options(tolerance_in_h), pool); }
};

}  // namespace

TEST_CASE("MLS lattice: positions within the tolerance of the exact map, normals close, any thread count") {
  const double h = 0.004;
  const MlsDeformation<3> map = drag(0.5 * h);
  const PointSet<3> start = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 40000);
  PointSet<3> exact = start;
  ThreadPool one(1), two(2);
  map.apply(exact, one);
  const MlsLatticeOptions options{8.0 * h, 0.01 * h, 4, true};
  PointSet<3> fast = start, fast2 = start;
  std::vector<float> strain, strain2;
  const MlsLatticeStats stats = apply_on_lattice(map, fast, &strain, options, one);
  apply_on_lattice(map, fast2, &strain2, options, two);
  CHECK_FALSE(stats.fell_back);
  CHECK(stats.refined_cells > 0);                 // near the handles
  CHECK(stats.exact_points < start.size() / 10);  // most points interpolate
  double worst = 0.0, worst_normal = 0.0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    worst = std::max(worst, (fast.positions[i] - exact.positions[i]).norm());
    worst_normal = std::max(worst_normal, (fast.normals[i] - exact.normals[i]).norm());
  }
  MESSAGE("largest position error " << worst / h << " h, normal error " << worst_normal);
  CHECK(worst <= 0.01 * h);
  CHECK(worst_normal < 1e-3);
  CHECK(fast.positions == fast2.positions);
  CHECK(fast.normals == fast2.normals);
  CHECK(strain == strain2);
}

TEST_CASE("MLS lattice: the strain of a rigid motion is zero, of a uniform scaling s is (s^2 - 1) sqrt(D) / 2") {
  const double h = 0.004;
  const MlsLatticeOptions options{8.0 * h, 0.01 * h, 4, true};
  const PointSet<3> start = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 20000);
  ThreadPool pool(2);
  const std::vector<Vec<3>> handles = drag(0.0).from();
  std::vector<Vec<3>> moved = handles, scaled = handles;
  for (Vec<3>& p : moved) p += Vec<3>(0.01, -0.02, 0.005);
  for (Vec<3>& p : scaled) p = Vec<3>(0.5, 0.5, 0.5) + 1.01 * (p - Vec<3>(0.5, 0.5, 0.5));
  PointSet<3> points = start;
  std::vector<float> strain;
  apply_on_lattice(MlsDeformation<3>(handles, moved), points, &strain, options, pool);
  for (const float s : strain) REQUIRE(s < 1e-9F);
  points = start;
  strain.clear();
  apply_on_lattice(MlsDeformation<3>(handles, scaled, MlsKind::similarity), points, &strain, options, pool);
  const double expected = 0.5 * (1.01 * 1.01 - 1.0) * std::sqrt(3.0);
  for (const float s : strain) REQUIRE(s == doctest::Approx(expected).epsilon(1e-6));
}

TEST_CASE("MLS lattice: strain accumulates over steps; a drag of h/2 strains by far less than the limit per step") {
  const double h = 0.004;
  const MlsLatticeOptions options{8.0 * h, 0.01 * h, 4, true};
  PointSet<3> points = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 20000);
  ThreadPool pool(2);
  std::vector<float> strain;
  apply_on_lattice(drag(0.5 * h), points, &strain, options, pool);
  const float once = *std::max_element(strain.begin(), strain.end());
  apply_on_lattice(drag(0.5 * h), points, &strain, options, pool);
  const float twice = *std::max_element(strain.begin(), strain.end());
  MESSAGE("largest strain after one step " << once << ", after two " << twice);
  CHECK(once > 1e-4F);
  CHECK(once < 0.02F);
  CHECK(twice > 1.5F * once);
}

TEST_CASE("MLS lattice without interpolation: the exact map's points, with the strain") {
  const double h = 0.004;
  const MlsDeformation<3> map = drag(0.5 * h);
  const PointSet<3> start = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.3, 20000);
  ThreadPool pool(2);
  PointSet<3> exact = start, mapped = start;
  map.apply(exact, pool);
  std::vector<float> strain;
  const MlsLatticeStats stats = apply_on_lattice(map, mapped, &strain, MlsLatticeOptions{8.0 * h, 0.0, 4, false}, pool);
  CHECK(stats.exact_points == start.size());
  CHECK(mapped.positions == exact.positions);
  CHECK(mapped.normals == exact.normals);
  CHECK(*std::max_element(strain.begin(), strain.end()) > 0.0F);
}

TEST_CASE("MLS deformation by the polar iteration: the SVD's map to rounding") {
  const double h = 0.004;
  for (const MlsKind kind : {MlsKind::rigid, MlsKind::similarity}) {
    MlsDeformation<3> svd(drag(0.0).from(), drag(7.0 * h).to(), kind);
    MlsDeformation<3> polar = svd;
    polar.use_polar_iteration(true);
    const PointSet<3> start = sample_sphere(Vec<3>(0.5, 0.5, 0.5), 0.32, 5000);
    ThreadPool pool(1);
    PointSet<3> a = start, b = start;
    svd.apply(a, pool);
    polar.apply(b, pool);
    double worst = 0.0, worst_normal = 0.0;
    for (std::size_t i = 0; i < start.size(); ++i) {
      worst = std::max(worst, (a.positions[i] - b.positions[i]).norm());
      worst_normal = std::max(worst_normal, (a.normals[i] - b.normals[i]).norm());
    }
    CHECK(worst < 1e-13);
    CHECK(worst_normal < 1e-12);
  }
}

TEST_CASE("MLS rest lattice: built once over the rest points, maps them to every step's handles near the tolerance") {
  RestSphere sphere;
  const MlsRestLattice<3> lattice = sphere.lattice(0.001);
  const std::vector<Vec<3>> from = drag(0.0).from();
  double worst = 0.0;
  for (const int step : {1, 5, 10}) {
    const MlsDeformation<3> map(from, drag(0.5 * sphere.h * step).to());
    PointSet<3> mapped, exact = sphere.rest;
    std::vector<float> strain;
    const MlsLatticeStats stats = lattice.map(map, sphere.rest, mapped, &strain, nullptr, sphere.pool);
    map.apply(exact, sphere.pool);
    CHECK_FALSE(stats.fell_back);
    CHECK(stats.exact_points < sphere.rest.size() / 10);
    CHECK(stats.nodes > stats.cells);  // the corners and their halo
    REQUIRE(mapped.size() == sphere.rest.size());
    for (std::size_t i = 0; i < sphere.rest.size(); ++i)
      worst = std::max(worst, (mapped.positions[i] - exact.positions[i]).norm());
  }
  // The check at the cells' centres bounds the error there; between centres
  // it may be somewhat larger.
  MESSAGE("largest position error over the three maps " << worst / sphere.h << " h");
  CHECK(worst <= 3.0 * 0.001 * sphere.h);
  PointSet<3> fewer = sphere.rest, out;
  fewer.positions.pop_back();
  fewer.normals.pop_back();
  CHECK_THROWS_AS(lattice.map(drag(sphere.h), fewer, out, nullptr, nullptr, sphere.pool), std::invalid_argument);
}

TEST_CASE("MLS rest lattice: each point's image is its own, whatever the points' order") {
  // The points are mapped cell by cell: each must still land at its own index.
  RestSphere sphere;
  PointSet<3> reversed = sphere.rest;
  std::reverse(reversed.positions.begin(), reversed.positions.end());
  std::reverse(reversed.normals.begin(), reversed.normals.end());
  const MlsRestLattice<3> lattice = sphere.lattice(0.001);
  const MlsRestLattice<3> reversed_lattice(reversed, sphere.options(0.001), sphere.pool);
  const MlsDeformation<3> map(drag(0.0).from(), drag(5.0 * sphere.h).to());
  PointSet<3> mapped, reversed_mapped;
  const MlsLatticeStats stats = lattice.map(map, sphere.rest, mapped, nullptr, nullptr, sphere.pool);
  reversed_lattice.map(map, reversed, reversed_mapped, nullptr, nullptr, sphere.pool);
  CHECK(stats.refined_cells > 0);  // both kinds of cells are read
  const std::size_t n = sphere.rest.size();
  REQUIRE(reversed_mapped.size() == n);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (reversed_mapped.positions[n - 1 - i] != mapped.positions[i] ||
        reversed_mapped.normals[n - 1 - i] != mapped.normals[i])
      ++differ;
  CHECK(differ == 0);
  CHECK(mapped.positions != sphere.rest.positions);
}

// How many of the 8 h cells holding `points` (aligned as the lattice's)
// would fail the centre check if their nodes' images were interpolated
// multilinearly.
std::size_t multilinear_failures(const MlsDeformation<3>& map, const PointSet<3>& points, double spacing,
                                 double tolerance) {
  Vec<3> lo = points.positions.front();
  for (const Vec<3>& p : points.positions) lo = lo.cwiseMin(p);
  const Vec<3> origin = lo.array() - spacing;
  std::set<std::array<std::int64_t, 3>> cells;
  for (const Vec<3>& p : points.positions) {
    const Vec<3> u = (p - origin) / spacing;
    cells.insert({static_cast<std::int64_t>(std::floor(u.x())), static_cast<std::int64_t>(std::floor(u.y())),
                  static_cast<std::int64_t>(std::floor(u.z()))});
  }
  std::size_t failures = 0;
  for (const auto& c : cells) {
    const Vec<3> corner = origin + spacing * Vec<3>(static_cast<double>(c[0]), static_cast<double>(c[1]),
                                                    static_cast<double>(c[2]));
    Vec<3> mean = Vec<3>::Zero();
    for (int v = 0; v < 8; ++v)
      mean += map.map(corner + spacing * Vec<3>(v & 1, (v >> 1) & 1, (v >> 2) & 1)) / 8.0;
    if ((mean - map.map(corner + Vec<3>::Constant(0.5 * spacing))).norm() > tolerance) ++failures;
  }
  return failures;
}

TEST_CASE("MLS rest lattice: third-order interpolation refines a few cells where multilinear would refine many") {
  RestSphere sphere;
  const MlsLatticeOptions options = sphere.options(0.002);
  const MlsDeformation<3> map(drag(0.0).from(), drag(10.0 * sphere.h).to());
  PointSet<3> mapped;
  const MlsLatticeStats stats = sphere.lattice(0.002).map(map, sphere.rest, mapped, nullptr, nullptr, sphere.pool);
  const std::size_t multilinear = multilinear_failures(map, sphere.rest, options.spacing, options.tolerance);
  MESSAGE(stats.refined_cells << " of " << stats.cells << " cells refined; multilinear would fail " << multilinear);
  CHECK(multilinear > 4 * stats.refined_cells);
}

TEST_CASE("MLS rest lattice: the strain added is the step's, from the last map's node images") {
  RestSphere sphere;
  const MlsRestLattice<3> lattice = sphere.lattice(0.001);
  const std::vector<Vec<3>> from = drag(0.0).from();
  MlsNodeImages<3> last;
  std::vector<float> summed;
  PointSet<3> mapped;
  // Out by 6 h and back in one step: the whole map ends at the identity, each step strained.
  lattice.map(MlsDeformation<3>(from, drag(6.0 * sphere.h).to()), sphere.rest, mapped, &summed, &last, sphere.pool);
  REQUIRE_FALSE(last.empty());
  const float out = *std::max_element(summed.begin(), summed.end());
  lattice.map(MlsDeformation<3>(from, from), sphere.rest, mapped, &summed, &last, sphere.pool);
  const float back = *std::max_element(summed.begin(), summed.end());
  MESSAGE("largest strain after the pull " << out << ", after the return " << back);
  CHECK(out > 1e-3F);
  CHECK(back > 1.8F * out);
  // The same second map measured from the rest state: no strain at all.
  std::vector<float> from_rest;
  lattice.map(MlsDeformation<3>(from, from), sphere.rest, mapped, &from_rest, nullptr, sphere.pool);
  CHECK(*std::max_element(from_rest.begin(), from_rest.end()) < 1e-9F);
}

TEST_CASE("MLS lattice: a refined cell maps and checks only the sub-cells that hold its points") {
  RestSphere s;
  const MlsDeformation<3> map = drag(0.5 * s.h);
  PointSet<3> mapped;
  const MlsLatticeStats stats = s.lattice(0.001).map(map, s.rest, mapped, nullptr, nullptr, s.pool);
  REQUIRE(stats.refined_cells > 0);
  // Without regions every cell is checked at its centre; the rest is the refined cells' sub-nodes and checks.
  const std::size_t refined_evaluations = stats.evaluations - stats.exact_points - stats.nodes - stats.cells;
  const std::size_t whole_sub_lattices = stats.refined_cells * (5 * 5 * 5 + 4 * 4 * 4);
  MESSAGE(refined_evaluations << " evaluations in " << stats.refined_cells << " refined cells, of "
                              << whole_sub_lattices << " for their whole sub-lattices");
  CHECK(refined_evaluations > 0);
  // A sphere's surface crosses a few of a cell's 64 sub-cells.
  CHECK(2 * refined_evaluations < whole_sub_lattices);
}
