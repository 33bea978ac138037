// Third-party files in each format people bring: CGAL's demo data (Debian's
// libcgal-demo), unpacked by the `cgal_data` test fixture into the folder
// named by AMLS_CGAL_DATA.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "real_data_files.hpp"

using namespace amls;
using amls::test::data_file;

namespace {

// Every normal of unit length.
bool unit_normals(const LoadedPointSet& read) {
  for (const Vec<3>& n : read.points.normals)
    if (std::abs(n.norm() - 1.0) > 1e-9) return false;
  return true;
}

// The fraction of normals pointing away from the centroid: near 1 for a closed, roundish scan with outward normals.
double outward_fraction(const LoadedPointSet& read) {
  Vec<3> centroid = Vec<3>::Zero();
  for (const Vec<3>& p : read.points.positions) centroid += p;
  centroid /= static_cast<double>(read.points.size());
  std::size_t outward = 0;
  for (std::size_t i = 0; i < read.points.size(); ++i)
    outward += read.points.normals[i].dot(read.points.positions[i] - centroid) > 0.0 ? 1 : 0;
  return static_cast<double>(outward) / static_cast<double>(read.points.size());
}

}  // namespace

TEST_CASE("real data, OFF: the bunny as a mesh, the kitten (no faces) as a point set") {
  const std::string bunny = data_file("meshes/bunny00.off");
  CHECK(is_mesh_file(bunny));
  const TriangleMesh mesh = read_mesh(bunny);
  CHECK(mesh.vertices.size() == 37706);
  CHECK(mesh.triangles.size() == 75408);

  const std::string kitten = data_file("points_3/kitten.off");
  CHECK_FALSE(is_mesh_file(kitten));
  const LoadedPointSet off = read_point_set(kitten);
  CHECK(off.points.size() == 5210);
  CHECK_FALSE(off.has_normals);
  // The same scan as kitten.xyz, with fewer digits.
  const LoadedPointSet xyz = read_point_set(data_file("points_3/kitten.xyz"));
  REQUIRE(xyz.points.size() == 5210);
  double farthest = 0.0;
  for (std::size_t i = 0; i < 5210; ++i)
    farthest = std::max(farthest, (off.points.positions[i] - xyz.points.positions[i]).norm());
  CHECK(farthest < 1e-5);
}

TEST_CASE("real data, text columns: the kitten and CGAL's .pwn with normals, the radar scan without") {
  const LoadedPointSet kitten = read_point_set(data_file("points_3/kitten.xyz"));
  CHECK(kitten.warnings.empty());
  CHECK(kitten.dimension == 3);
  CHECK(kitten.has_normals);
  CHECK(kitten.points.size() == 5210);
  CHECK(unit_normals(kitten));
  CHECK(outward_fraction(kitten) > 0.85);  // not convex: the ears and the tail

  const LoadedPointSet cube = read_point_set(data_file("points_3/cube.pwn"));
  CHECK(cube.has_normals);
  CHECK(cube.points.size() == 50000);
  CHECK(unit_normals(cube));  // unoriented (about half point inward): CGAL's orientation test data

  const LoadedPointSet radar = read_point_set(data_file("points_3/radar.xyz"));
  CHECK_FALSE(radar.has_normals);
  CHECK(radar.points.size() == 20950);
}

TEST_CASE("real data, PLY: binary doubles, ASCII with an int segment_index, and two zero normals repaired") {
  const LoadedPointSet hippo = read_point_set(data_file("points_3/hippo1.ply"));
  CHECK(hippo.warnings.empty());
  CHECK(hippo.has_normals);
  CHECK(hippo.points.size() == 6104);
  CHECK(unit_normals(hippo));

  const std::string building_path = data_file("points_3/building.ply");
  CHECK_FALSE(is_mesh_file(building_path));
  const LoadedPointSet building = read_point_set(building_path);
  CHECK(building.has_normals);
  CHECK(building.points.size() == 100000);
  CHECK(unit_normals(building));

  // hippo2.ply has two vertices (2207 and another) whose normal is (0, 0, 0).
  const LoadedPointSet hippo2 = read_point_set(data_file("points_3/hippo2.ply"));
  CHECK(hippo2.has_normals);
  CHECK(hippo2.points.size() == 4387);
  REQUIRE(hippo2.warnings.size() == 1);
  CHECK(hippo2.warnings[0].find("2 points have a zero-length or non-finite normal (the first at vertex 2207)") !=
        std::string::npos);
  CHECK(unit_normals(hippo2));
  // The repaired normal agrees with its neighbours', as the given ones do.
  const Vec<3>& p = hippo2.points.positions[2207];
  const Vec<3>& n = hippo2.points.normals[2207];
  double agreement = 0.0;
  for (std::size_t j = 0; j < hippo2.points.size(); ++j)
    if (j != 2207 && (hippo2.points.positions[j] - p).norm() < 0.01) agreement += n.dot(hippo2.points.normals[j]);
  CHECK(agreement > 0.0);
}
