#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/surface_samples.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

TEST_CASE("mesh io: OBJ faces, polygons fan-triangulated, v/vt/vn corners and negative indices") {
  TempDir dir;
  write_text(dir.file("quad.obj"),
             "# a unit square and a triangle\r\nmtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
             "g square\nf 1/1/1 2/1/1 3//1 4\nv 0 0 1\nf -5 -4 -1\n");
  const TriangleMesh mesh = read_mesh(dir.file("quad.obj"));
  REQUIRE(mesh.vertices.size() == 5);
  REQUIRE(mesh.triangles.size() == 3);
  CHECK(mesh.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(mesh.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
  CHECK(mesh.triangles[2] == std::array<std::uint32_t, 3>{0, 1, 4});
  CHECK(is_mesh_file(dir.file("quad.obj")));
  write_text(dir.file("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir.file("bad.obj")),
                       doctest::Contains("bad.obj: line 3: vertex index 3 is out of range"), std::runtime_error);
  write_text(dir.file("bad2.obj"), "v 0 0 x\n");
  CHECK_THROWS_WITH(read_mesh(dir.file("bad2.obj")), doctest::Contains("line 1: 'x' is not a finite number"));
}

TEST_CASE("mesh io: PLY faces, ASCII and binary, with the vertex_indices list") {
  TempDir dir;
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  write_text(dir.file("a.ply"), header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const TriangleMesh a = read_mesh(dir.file("a.ply"));
  CHECK(a.vertices.size() == 4);
  REQUIRE(a.triangles.size() == 2);
  CHECK(a.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
  CHECK(is_mesh_file(dir.file("a.ply")));
  write_text(dir.file("bad.ply"), header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 9\n");
  CHECK_THROWS_WITH(read_mesh(dir.file("bad.ply")), doctest::Contains("face 1: vertex index 9 is out of range"));

  // Binary little endian: one quad (4 indices), triangulated into two.
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n";
  const double xyz[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  bytes.push_back(4);
  const std::uint32_t quad[4] = {0, 1, 2, 3};
  bytes.append(reinterpret_cast<const char*>(quad), sizeof quad);
  write_text(dir.file("b.ply"), bytes);
  const TriangleMesh b = read_mesh(dir.file("b.ply"));
  REQUIRE(b.triangles.size() == 2);
  CHECK(b.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
  CHECK(b.vertices[2] == Vec<3>(1, 1, 0));

  write_text(dir.file("points.ply"),
             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n0 0 0\n");
  CHECK_FALSE(is_mesh_file(dir.file("points.ply")));
  CHECK(read_mesh(dir.file("points.ply")).triangles.empty());
}

TEST_CASE(
    "mesh io: a PLY point cloud with 'element face 0' (as MeshLab saves one) is a point set, not a faceless mesh") {
  TempDir dir;
  std::string text =
      "ply\nformat ascii 1.0\ncomment MeshLab\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty uchar red\n"
      "element face 0\nproperty list uchar int vertex_indices\nend_header\n";
  text += "0 0 0 0 0 -1 10\n1 0 0 0 0 -1 20\n0 1 0 0 0 -1 30\n0 0 1 1 1 1 40\n";
  write_text(dir.file("cloud.PLY"), text);
  CHECK_FALSE(is_mesh_file(dir.file("cloud.PLY")));
  SurfaceSampleOptions options;
  options.spacing = 0.1;
  options.normal_radius = 0.3;
  const SurfaceSamples samples = load_surface_samples(dir.file("cloud.PLY"), options);
  CHECK(samples.points.size() == 4);
  CHECK(samples.source.find("point set of 4 points with normals") != std::string::npos);
  CHECK_THROWS_WITH_AS(read_mesh(dir.file("cloud.3mf")), doctest::Contains("unknown mesh file extension '.3mf'"),
                       std::invalid_argument);
}

namespace {

// A tetrahedron's four faces as STL facets, wound outward: ASCII text.
const char* kAsciiTetra =
    "solid tetra\n"
    "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n endloop\nendfacet\n"
    "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n endloop\nendfacet\n"
    "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n endloop\nendfacet\n"
    "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n endloop\nendfacet\n"
    "endsolid tetra\n";

// The same as binary STL (the header beginning with "solid", as some programs write it).
std::string binary_tetra() {
  const float corners[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                                  {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                                  {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                  {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::string bytes = "solid written by a program that says so in a binary header";
  bytes.resize(80, ' ');
  const std::uint32_t count = 4;
  bytes.append(reinterpret_cast<const char*>(&count), 4);  // little endian on the machines amls builds for
  for (const auto& triangle : corners) {
    bytes.append(12, '\0');  // a normal of zeros, as many writers leave it
    bytes.append(reinterpret_cast<const char*>(triangle), sizeof(triangle));
    bytes.append(2, '\0');
  }
  return bytes;
}

}  // namespace

TEST_CASE("mesh io: STL, ASCII and binary, its corners merged into shared vertices") {
  TempDir dir;
  write_text(dir.file("ascii.stl"), kAsciiTetra);
  write_text(dir.file("binary.STL"), binary_tetra());
  for (const char* name : {"ascii.stl", "binary.STL"}) {
    CAPTURE(name);
    CHECK(is_mesh_file(dir.file(name)));
    const TriangleMesh mesh = read_mesh(dir.file(name));
    REQUIRE(mesh.vertices.size() == 4);  // 12 corners, 4 positions
    REQUIRE(mesh.triangles.size() == 4);
    CHECK(mesh.vertices[0] == Vec<3>(0, 0, 0));
    CHECK(mesh.vertices[1] == Vec<3>(0, 1, 0));
    CHECK(mesh.vertices[2] == Vec<3>(1, 0, 0));
    CHECK(mesh.vertices[3] == Vec<3>(0, 0, 1));
    CHECK(mesh.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(mesh.triangles[3] == std::array<std::uint32_t, 3>{2, 1, 3});
    // Closed and wound outward, so its samples point out and its inside is known.
    SurfaceSampleOptions options;
    options.spacing = 0.05;
    const SurfaceSamples samples = load_surface_samples(dir.file(name), options);
    CHECK(samples.closed_mesh.has_value());
    CHECK(samples.warnings.empty());
  }
  // An STL file is a mesh, never a point set.
  CHECK_THROWS_WITH_AS(read_point_set(dir.file("ascii.stl"), 0),
                       doctest::Contains("a .stl file holds a triangle mesh, not a point set"), std::invalid_argument);
}

TEST_CASE("mesh io: broken STL files are refused with the line or triangle") {
  TempDir dir;
  auto error_of = [&](const std::string& text) {
    write_text(dir.file("bad.stl"), text);
    try {
      read_mesh(dir.file("bad.stl"));
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string file = dir.file("bad.stl");
  CHECK(error_of("") == file + ": empty file: expected an STL file");
  CHECK(error_of("hello\n") == file + ": line 1: expected an STL file: binary, or ASCII starting with 'solid'");
  CHECK(error_of("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n") ==
        file + ": line 7: a facet of 2 vertices (STL facets are triangles)");
  CHECK(error_of("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\n") ==
        file + ": line 4: 'nan' is not a finite number");
  CHECK(error_of("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n") == file + ": the file ends inside a facet");
  CHECK(error_of("solid s\nvertex 0 0 0\n") == file + ": line 2: 'vertex' outside a facet");
  // A binary file whose count says more triangles than it holds is not binary; nor is it ASCII.
  std::string cut = binary_tetra();
  cut.resize(cut.size() - 10);
  CHECK(error_of(cut) == file + ": neither ASCII STL (binary bytes on line 1) nor binary STL (274 bytes where its "
                                "count of 4 triangles needs 284)");
  // A binary corner that is not a finite number.
  std::string nan = binary_tetra();
  const float bad = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + 84 + 50 + 12, &bad, 4);
  CHECK(error_of(nan) == file + ": triangle 1: a corner with a non-finite coordinate");
}
