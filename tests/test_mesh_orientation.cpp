#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "core/io/mesh_orientation.hpp"
#include "core/io/surface_samples.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// A tetrahedron wound outward.
TriangleMesh tetrahedron() {
  TriangleMesh mesh;
  mesh.vertices = {Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

// Whether every edge that two triangles share is run through in opposite directions.
bool consistently_wound(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  for (const auto& [edge, count] : directed)
    if (count > 1) return false;
  return true;
}

void turn(TriangleMesh& mesh, std::size_t t) { std::swap(mesh.triangles[t][1], mesh.triangles[t][2]); }

}  // namespace

TEST_CASE("mesh orientation: triangles wound against their neighbours are turned, the majority's winding kept") {
  TriangleMesh mesh = tetrahedron();
  const TriangleMesh outward = mesh;
  CHECK(orient_consistently(mesh).turned == 0);  // already consistent: left as it is
  CHECK(mesh.triangles == outward.triangles);

  turn(mesh, 1);  // one of four against the others
  MeshOrientation result = orient_consistently(mesh);
  CHECK(result.turned == 1);
  CHECK(result.conflicts == 0);
  CHECK(mesh.triangles == outward.triangles);

  mesh = outward;
  turn(mesh, 0);
  turn(mesh, 2);
  turn(mesh, 3);  // three of four turned: the majority's winding is now inward, and it is kept
  result = orient_consistently(mesh);
  CHECK(result.turned == 1);
  CHECK(consistently_wound(mesh));
  CHECK(mesh.triangles[1] == std::array<std::uint32_t, 3>{0, 3, 1});

  // Two parts, each wound on its own: the second tetrahedron, shifted, with one triangle turned.
  TriangleMesh two = outward;
  for (const Vec<3>& v : outward.vertices) two.vertices.push_back(v + Vec<3>(5, 0, 0));
  for (auto t : outward.triangles) {
    for (auto& v : t) v += 4;
    two.triangles.push_back(t);
  }
  turn(two, 6);
  CHECK(orient_consistently(two).turned == 1);
  CHECK(consistently_wound(two));
}

TEST_CASE("mesh orientation: a one-sided strip cannot be wound alike, and says so") {
  // A Moebius strip of 8 quads (16 triangles): its two ends joined with a half turn.
  TriangleMesh strip;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / n;
    const Vec<3> centre(std::cos(a), std::sin(a), 0.0);
    const Vec<3> across = 0.3 * (std::cos(a / 2) * Vec<3>(std::cos(a), std::sin(a), 0.0) + std::sin(a / 2) * Vec<3>::UnitZ());
    strip.vertices.push_back(centre + across);
    strip.vertices.push_back(centre - across);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t a = 2 * i, b = 2 * i + 1;
    // The last quad joins vertex 2i to the first's far side: the half turn.
    const std::uint32_t c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    strip.triangles.push_back({a, b, d});
    strip.triangles.push_back({a, d, c});
  }
  const MeshOrientation result = orient_consistently(strip);
  CHECK(result.conflicts == 1);
}

TEST_CASE("mesh orientation: a shuffled closed mesh opens closed, with its inside, and a warning") {
  TempDir dir;
  // The tetrahedron with two of its faces turned, as CGAL's tet-shuffled.off.
  write_text(dir.file("shuffled.off"), "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 3 1\n3 0 2 3\n3 1 2 3\n");
  const SurfaceInput input = read_surface_input(dir.file("shuffled.off"), 0);
  CHECK(input.orientation.turned == 2);
  CHECK(consistently_wound(input.mesh));
  SurfaceSampleOptions options;
  options.spacing = 0.05;
  const SurfaceSamples samples = surface_samples(input, options);
  CHECK(samples.closed_mesh.has_value());
  REQUIRE_FALSE(samples.warnings.empty());
  CHECK(samples.warnings[0] == dir.file("shuffled.off") +
                                   ": 2 of 4 triangles were wound against their neighbours and were turned to agree "
                                   "with them");
  // Every sample's normal points outward (the centroid is inside).
  for (std::size_t i = 0; i < samples.points.size(); ++i)
    CHECK(samples.points.normals[i].dot(samples.points.positions[i] - Vec<3>::Constant(0.25)) > 0.0);
}
