#include <doctest/doctest.h>

#include "core/io/point_set_io.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/surface_samples.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

TEST_CASE("surface samples: point sets with and without normals, and meshes, all come out oriented") {
  TempDir dir;
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 0.5, 1500);
  write_point_set(dir.file("with.ply"), sphere, PointFileFormat::ply_binary_little_endian);
  PointSet<3> bare = sphere;
  bare.normals.clear();
  write_point_set(dir.file("bare.xyz"), bare, PointFileFormat::xyz);
  write_text(dir.file("tetra.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  SurfaceSampleOptions options;
  options.spacing = 0.05;
  options.normal_radius = 0.1;

  const SurfaceSamples with = load_surface_samples(dir.file("with.ply"), options);
  CHECK(with.points.size() == 1500);
  CHECK(with.source.find("with normals") != std::string::npos);

  const SurfaceSamples estimated = load_surface_samples(dir.file("bare.xyz"), options);
  REQUIRE(estimated.points.size() == 1500);
  CHECK(estimated.source.find("normals estimated") != std::string::npos);
  for (std::size_t i = 0; i < sphere.size(); ++i) CHECK(estimated.points.normals[i].dot(sphere.normals[i]) > 0.99);

  const SurfaceSamples mesh = load_surface_samples(dir.file("tetra.obj"), options);
  CHECK(mesh.warnings.empty());
  options.estimate_normals = true;  // nothing to set aside on a mesh: the same samples, and a warning saying so
  const SurfaceSamples asked = load_surface_samples(dir.file("tetra.obj"), options);
  CHECK(asked.points.positions == mesh.points.positions);
  CHECK(asked.points.normals == mesh.points.normals);
  REQUIRE(asked.warnings.size() == 1);
  CHECK(asked.warnings[0] == dir.file("tetra.obj") +
                                 ": a mesh's samples take its faces' normals; there are no point normals to set aside "
                                 "and estimate");
  options.estimate_normals = false;
  CHECK(mesh.dimension == 3);
  CHECK(mesh.points.size() > 100);
  CHECK(mesh.source.find("mesh of 4 triangles") != std::string::npos);
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    CHECK(mesh.points.normals[i].dot(mesh.points.positions[i] - Vec<3>::Constant(0.25)) > 0.0);

  options.dimension = 2;
  CHECK_THROWS_WITH(load_surface_samples(dir.file("tetra.obj"), options), doctest::Contains("3D shape, not 2D"));
  write_text(dir.file("none.xyz"), "# nothing\n");
  CHECK_THROWS_WITH(load_surface_samples(dir.file("none.xyz"), SurfaceSampleOptions{}),
                    doctest::Contains("none.xyz: holds no points"));
}
