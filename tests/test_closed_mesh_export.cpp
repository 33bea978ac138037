#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "core/io/mesh_inside.hpp"
#include "core/io/mesh_sampling.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/shape_opening.hpp"
#include "mesh_fixtures.hpp"
#include "temp_dir.hpp"

using namespace amls;
using amls::test::box_mesh;
using amls::test::enclosed_volume;

namespace {

// A latitude-longitude sphere of radius r: enough triangles (2 * 48 * 24)
// that MeshInside's tree sums most of them as dipoles.
TriangleMesh uv_sphere(double r) {
  constexpr std::uint32_t kAround = 48, kRings = 24;
  TriangleMesh m;
  m.vertices.emplace_back(0.0, 0.0, -r);
  for (std::uint32_t i = 1; i < kRings; ++i)
    for (std::uint32_t j = 0; j < kAround; ++j) {
      const double polar = std::numbers::pi * i / kRings, azimuth = 2.0 * std::numbers::pi * j / kAround;
      m.vertices.emplace_back(r * std::sin(polar) * std::cos(azimuth), r * std::sin(polar) * std::sin(azimuth),
                              -r * std::cos(polar));
    }
  m.vertices.emplace_back(0.0, 0.0, r);
  const auto top = static_cast<std::uint32_t>(m.vertices.size() - 1);
  auto ring = [](std::uint32_t i, std::uint32_t j) { return 1 + (i - 1) * kAround + j % kAround; };
  for (std::uint32_t j = 0; j < kAround; ++j) {
    m.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
    m.triangles.push_back({top, ring(kRings - 1, j), ring(kRings - 1, j + 1)});
    for (std::uint32_t i = 1; i + 1 < kRings; ++i) {
      m.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
  }
  return m;
}

// A prism along y whose cross-section is a thin triangle (10 degrees at its
// sharp edge): a fin whose two sides meet within Delta.
TriangleMesh fin() {
  TriangleMesh m;
  for (const double y : {0.3, 0.7})
    for (const auto& [x, z] : {std::pair{0.2, 0.43}, std::pair{0.2, 0.53}, std::pair{0.8, 0.5}}) m.vertices.emplace_back(x, y, z);
  m.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5}};
  return m;
}

long euler_characteristic(const MeshExport& mesh) {
  return static_cast<long>(mesh.vertices) - static_cast<long>(mesh.topology.facets) + static_cast<long>(mesh.cells);
}

}  // namespace

TEST_CASE("winding number: +-1 inside a closed mesh, 0 outside, whichever way its faces are wound") {
  for (const bool inward : {false, true}) {
    const TriangleMesh box = box_mesh(Vec<3>::Zero(), Vec<3>(1.0, 2.0, 0.1), inward);
    CHECK(winding_number(box, Vec<3>(0.5, 1.0, 0.05)) == doctest::Approx(inward ? -1.0 : 1.0));
    CHECK(winding_number(box, Vec<3>(0.999, 1.999, 0.001)) == doctest::Approx(inward ? -1.0 : 1.0));
    CHECK(winding_number(box, Vec<3>(0.5, 1.0, 0.11)) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(winding_number(box, Vec<3>(-3.0, 5.0, 2.0)) == doctest::Approx(0.0).epsilon(1e-12));
    CHECK(MeshInside(box).inside(Vec<3>(0.2, 0.2, 0.02)));
    CHECK_FALSE(MeshInside(box).inside(Vec<3>(1.01, 0.2, 0.02)));
  }
}

TEST_CASE("only a closed, consistently wound mesh has an inside to ask") {
  TriangleMesh box = box_mesh(Vec<3>::Zero(), Vec<3>::Ones());
  CHECK(closed_and_consistently_wound(box));
  CHECK(closed_and_consistently_wound(box_mesh(Vec<3>::Zero(), Vec<3>::Ones(), true)));
  std::swap(box.triangles[3][1], box.triangles[3][2]);  // one face wound the other way
  CHECK_FALSE(closed_and_consistently_wound(box));
  box.triangles.erase(box.triangles.begin() + 3);  // a hole
  CHECK_FALSE(closed_and_consistently_wound(box));
}

TEST_CASE("a closed input mesh gives a closed mesh: the input's inside decides the sides") {
  // A slab thinner than Delta: the orientation filter makes F jump in sign
  // between its faces, and past its edges the jumps run on until F is
  // undefined, where the mesh was left open. With the input's sides the
  // jumps are not followed: the mesh never reaches where F is undefined.
  const double h = 0.02;
  const TriangleMesh slab = box_mesh(Vec<3>(0.25, 0.25, 0.48), Vec<3>(0.75, 0.75, 0.52));
  PointSetResampling options;
  options.spacing = h;
  options.threads = 2;
  const ResampledPointSet<3> resampled = resample_point_set(sample_mesh(slab, h).points, options);
  amls::test::TempDir dir;
  const MeshExport open = export_resampled_mesh(dir.file("open.ply"), resampled, options);
  CHECK(open.topology.boundary > 0);
  const MeshExport closed = export_resampled_mesh(dir.file("closed.ply"), resampled, options, &slab);
  CHECK(closed.topology.closed());
  CHECK(open.stats.undefined_cubes > 0);
  CHECK(closed.stats.undefined_cubes == 0);
  CHECK(closed.stats.overruled_signs > 0);
  CHECK(euler_characteristic(closed) == 2);
  // The slab's mesh, not the jumps': no larger than F's open mesh.
  CHECK(closed.vertices < open.vertices);
}

TEST_CASE("MeshInside's tree gives the exact winding number's inside, and its value within 2e-2") {
  const TriangleMesh sphere = uv_sphere(0.4);
  const MeshInside inside(sphere);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const Vec<3> x(coordinate(random), coordinate(random), coordinate(random));
    const double exact = winding_number(sphere, x);
    CHECK(std::abs(inside.winding_number(x) - exact) < 2e-2);  // measured: at most 1.04e-2
    CHECK(inside.inside(x) == (std::abs(exact) > 0.5));
  }
}

TEST_CASE("a closed input's mesh has the input's topology: a sharp fin gives no handle") {
  // The fin's two sides come within Delta along its sharp edge, where F jumps
  // in sign; where F's sign decided, the mesh had a handle there (Euler
  // characteristic 0) and enclosed 14 % more than the fin.
  const double h = 0.02;
  const TriangleMesh shape = fin();
  PointSetResampling options;
  options.spacing = h;
  options.threads = 2;
  const ResampledPointSet<3> resampled = resample_point_set(sample_mesh(shape, h).points, options);
  amls::test::TempDir dir;
  const MeshExport exported = export_resampled_mesh(dir.file("fin.ply"), resampled, options, &shape);
  REQUIRE(exported.topology.closed());
  CHECK(euler_characteristic(exported) == 2);
  CHECK(exported.stats.overruled_signs > 0);
  const TriangleMesh mesh = read_mesh(dir.file("fin.ply"));
  // Measured -2.2 %: the fin's sharp edge is cut off between grid vertices.
  CHECK(enclosed_volume(mesh.vertices, mesh.triangles) ==
        doctest::Approx(enclosed_volume(shape.vertices, shape.triangles)).epsilon(0.03));
}

namespace {

// A mesh read as a file would be, opened by the rules of `amls resample`.
OpenedShape open_mesh(const std::string& name, TriangleMesh mesh) {
  SurfaceInput input;
  input.path = name;
  input.is_mesh = true;
  input.mesh = std::move(mesh);
  ShapeOpening opening;
  opening.resampling.threads = 2;
  ThreadPool pool(2);
  return open_shape(std::move(input), opening, pool);
}

// The opened shape resampled at its h and exported with its closed input mesh;
// REQUIREs that the mesh is closed, and returns its Euler characteristic and
// enclosed volume.
std::pair<long, double> closed_export(const std::string& name, const OpenedShape& opened) {
  REQUIRE(opened.closed_mesh);
  PointSetResampling options;
  options.threads = 2;
  options.spacing = opened.spacing.h;
  const ResampledPointSet<3> resampled = resample_point_set(opened.points, options);
  amls::test::TempDir dir;
  const MeshExport exported = export_resampled_mesh(dir.file(name + ".ply"), resampled, options, &*opened.closed_mesh);
  REQUIRE(exported.topology.closed());
  const TriangleMesh mesh = read_mesh(dir.file(name + ".ply"));
  return {euler_characteristic(exported), enclosed_volume(mesh.vertices, mesh.triangles)};
}

}  // namespace

TEST_CASE("a coarse polyhedron gets an h fine enough for its shape, and its mesh the polyhedron's volume") {
  // A cube's 8 vertices lie a side apart: their rule gives h = 1.41 on a side
  // of 2, a grid of two cells that encloses tens of percent too much or too little.
  const OpenedShape opened = open_mesh("cube", box_mesh(Vec<3>::Zero(), Vec<3>::Constant(2.0)));
  CHECK(opened.spacing.h == doctest::Approx(2.0 / 32));
  const auto [euler, volume] = closed_export("cube", opened);
  CHECK(euler == 2);
  CHECK(volume == doctest::Approx(8.0).epsilon(0.01));
}

TEST_CASE("a thin polyhedron gets h from its thickness, and its mesh the polyhedron's volume") {
  // CGAL's beam.off: 0.4 x 0.4 x 3.6 in 8 vertices. At its longest side / 32
  // the beam is 3.6 h thick and its rounded edges lost 12 % of the volume.
  const TriangleMesh beam = box_mesh(Vec<3>::Zero(), Vec<3>(0.4, 0.4, 3.6));
  const MeshMeasures measures = measure_mesh(beam);
  CHECK(measures.volume == doctest::Approx(0.4 * 0.4 * 3.6));
  CHECK(measures.mean_thickness == doctest::Approx(3.0 * 0.576 / (4 * 0.4 * 3.6 + 2 * 0.16)));
  const OpenedShape opened = open_mesh("beam", beam);
  CHECK(opened.spacing.h == doctest::Approx(measures.mean_thickness / 16));
  CHECK(opened.spacing.reason.find("mean thickness") != std::string::npos);
  const auto [euler, volume] = closed_export("beam", opened);
  CHECK(euler == 2);
  // Measured -0.42 % (-12.2 % at the longest side / 32).
  CHECK(volume == doctest::Approx(0.576).epsilon(0.01));
}

TEST_CASE("a smooth mesh dense in vertices keeps its vertices' h, coarser than its thickness bound") {
  // A sphere of radius 1 in 1,106 vertices: its vertices' rule gives about
  // r / 15, coarser than r / 16, but its vertices, not large flat faces,
  // carry its shape (about 2 samples a vertex), and a smooth surface keeps
  // its volume at that h.
  const TriangleMesh sphere = uv_sphere(1.0);
  const OpenedShape opened = open_mesh("sphere", sphere);
  CHECK(opened.spacing.h > measure_mesh(sphere).mean_thickness / 16);
  CHECK(opened.spacing.reason.find("mean thickness") == std::string::npos);
  CHECK(opened.spacing.reason.find("4th nearest neighbour") != std::string::npos);
}
