#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"
#include "core/geometry/surface_scatter.hpp"
#include "core/io/mesh_io.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/shape_opening.hpp"
#include "tests/mesh_fixtures.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;

namespace {

constexpr std::size_t kPoints = 8000;
// Wider than the points' spacing on the unit sphere (about 0.04 between nearest neighbours).
constexpr double kNoise = 0.05;

// A standard normal deviate (Box-Muller) from mt19937's raw bits, which are
// the same on every platform, unlike std::normal_distribution's results; the
// two draws are sequenced, as operands of one expression would not be.
double standard_normal(std::mt19937& bits) {
  auto uniform = [&bits] { return (static_cast<double>(bits()) + 0.5) / 4294967296.0; };
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  return radius * std::cos(2.0 * std::numbers::pi * uniform());
}

// Samples of the unit sphere with their radii scattered by a normal law of
// standard deviation `noise`.
std::vector<Vec<3>> noisy_sphere(double noise) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, kPoints);
  std::mt19937 bits(7);
  std::vector<Vec<3>> out;
  for (const Vec<3>& p : sphere.positions) out.push_back(p * (1.0 + noise * standard_normal(bits)));
  return out;
}

// A point set without normals, opened as `amls resample` opens a file.
OpenedShape open_points(const std::vector<Vec<3>>& positions) {
  SurfaceInput input;
  input.path = "noisy.xyz";
  for (const Vec<3>& p : positions) input.point_set.points.add(p, Vec<3>::Zero());
  ShapeOpening opening;
  opening.resampling.threads = 2;
  ThreadPool pool(2);
  return open_shape(std::move(input), opening, pool);
}

}  // namespace

TEST_CASE("a clean surface is not noisy however it curves, and a noisy one measures its noise") {
  const SurfaceScatter clean = surface_scatter<3>(noisy_sphere(0.0));
  CHECK_FALSE(clean.noisy());
  CHECK(clean.thickness < 0.2);
  CHECK(clean.scatter == 0.0);
  const SurfaceScatter noisy = surface_scatter<3>(noisy_sphere(kNoise));
  CHECK(noisy.noisy());
  // The quadric absorbs a little of the noise (sphere_20k.xyz: 0.034 for 0.041).
  CHECK(noisy.scatter > 0.7 * kNoise);
  CHECK(noisy.scatter < 1.1 * kNoise);
  // Too few points to tell noise from shape.
  const std::vector<Vec<3>> all = noisy_sphere(kNoise);
  CHECK(surface_scatter<3>(std::vector<Vec<3>>(all.begin(), all.begin() + SurfaceScatter::kScatterNeighbours))
            .thickness == 0.0);
}

TEST_CASE("a curve's scatter: a noisy circle measures its noise, a clean one none") {
  constexpr int kCurvePoints = 2000;  // 0.0031 apart on the unit circle
  constexpr double kCurveNoise = 0.01;
  std::mt19937 bits(11);
  std::vector<Vec<2>> clean, noisy;
  for (int i = 0; i < kCurvePoints; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kCurvePoints;
    clean.emplace_back(std::cos(angle), std::sin(angle));
    noisy.push_back(clean.back() * (1.0 + kCurveNoise * standard_normal(bits)));
  }
  CHECK_FALSE(surface_scatter<2>(clean).noisy());
  const SurfaceScatter measured = surface_scatter<2>(noisy);
  CHECK(measured.noisy());
  CHECK(measured.scatter > 0.7 * kCurveNoise);
  CHECK(measured.scatter < 1.1 * kCurveNoise);
}

TEST_CASE("a clean scan keeps the h of its neighbours") {
  const std::vector<Vec<3>> clean = noisy_sphere(0.0);
  const OpenedShape shape = open_points(clean);
  CHECK(shape.spacing.h == sample_spacing<3>(clean).h);
  CHECK(shape.spacing.reason.find("scatter") == std::string::npos);
}

TEST_CASE("a noisy closed scan gets an h that resolves the surface, and a closed mesh near its volume") {
  const OpenedShape shape = open_points(noisy_sphere(kNoise));
  INFO(shape.spacing.reason);
  REQUIRE(shape.spacing.reason.find("scatter") != std::string::npos);
  CHECK(shape.spacing.h > 3.0 * kNoise);
  CHECK(shape.spacing.h < 4.4 * kNoise);
  PointSetResampling options;
  options.spacing = shape.spacing.h;
  options.threads = 2;
  options.widen_support = true;
  const ResampledPointSet<3> resampled = resample_point_set(shape.points, options);
  amls::test::TempDir dir;
  // At the neighbours' h (0.033) a like sphere (numpy's noise) gave 6,282 boundary edges.
  const MeshExport exported = export_resampled_mesh(dir.file("noisy.ply"), resampled, options);
  REQUIRE(exported.topology.closed());
  const TriangleMesh mesh = read_mesh(dir.file("noisy.ply"));
  // Measured -1.6 %: h is a fifth of the radius, and the chords cut inside.
  CHECK(amls::test::enclosed_volume(mesh.vertices, mesh.triangles) ==
        doctest::Approx(4.0 / 3.0 * std::numbers::pi).epsilon(0.03));
}
