#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/surface_samples.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// A unit cube's corners, and its six faces as quads wound counter-clockwise from outside.
const std::string kCubeVertices =
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const std::string kCubeFaces =
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
    "4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

}  // namespace

TEST_CASE("OFF meshes: counts on the header line or the next, comments anywhere, quads fan-triangulated") {
  TempDir dir;
  const std::vector<std::pair<const char*, std::string>> files{
      {"plain", "OFF\n8 6 12\n" + kCubeVertices + kCubeFaces},
      {"counts on the header line, CRLF, no edge count", "OFF 8 6\r\n" + kCubeVertices + kCubeFaces},
      {"comments before the header and within, blank lines",
       "# Output of a tool\n#CBP\nOFF # keyword\n\n8 6 0 # counts\n# vertices\n" + kCubeVertices + "\n# faces\n" +
           kCubeFaces + "\n# the end\n"},
      {"no keyword (Geomview's optional header)", "8 6 0\n" + kCubeVertices + kCubeFaces},
  };
  for (const auto& [what, text] : files) {
    INFO(what);
    const std::string path = dir.file("cube.off");
    write_text(path, text);
    CHECK(is_mesh_file(path));
    const TriangleMesh mesh = read_mesh(path);
    REQUIRE(mesh.vertices.size() == 8);
    CHECK(mesh.vertices[6] == Vec<3>(1, 1, 1));
    REQUIRE(mesh.triangles.size() == 12);
    CHECK(mesh.triangles[0] == std::array<std::uint32_t, 3>{0, 3, 2});
    CHECK(mesh.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 1});
  }
}

TEST_CASE("OFF variants: COFF and NCOFF colours are read past, NOFF normals, 4OFF's w divides, nOFF in 3D") {
  TempDir dir;
  const std::string path = dir.file("variant.off");
  // Colours of 3 or 4 values, integers or fractions, and a face colour, as CGAL's data has them.
  write_text(path,
             "COFF\n4 2 0\n0 0 0 0.9 0.0 0.0\n2 0 0 192 192 192 255\n0 2 0 1 1 1\n0 0 2 0 0 0 1\n"
             "3 0 2 1 255 0 0\n3 0 1 3\n");
  TriangleMesh mesh = read_mesh(path);
  CHECK(mesh.vertices.size() == 4);
  CHECK(mesh.vertices[1] == Vec<3>(2, 0, 0));
  CHECK(mesh.triangles.size() == 2);

  write_text(path, "NCOFF\n2 0 0\n0 0 0 0 0 2 255 0 0\n1 0 0 0 1 0 0 255 0\n");
  LoadedPointSet points = read_point_set(path);
  CHECK(points.has_normals);
  REQUIRE(points.points.size() == 2);
  CHECK(points.points.normals[0] == Vec<3>(0, 0, 1));  // normalised, with a warning
  CHECK(points.points.normals[1] == Vec<3>(0, 1, 0));
  CHECK(points.warnings.size() == 1);

  write_text(path, "4OFF\n2 0 0\n2 4 6 2\n1 1 1 0.5\n");
  points = read_point_set(path);
  CHECK_FALSE(points.has_normals);
  CHECK(points.points.positions[0] == Vec<3>(1, 2, 3));
  CHECK(points.points.positions[1] == Vec<3>(2, 2, 2));

  write_text(path, "nOFF 3 1 0 0\n1 2 3\n");
  CHECK(read_point_set(path).points.positions[0] == Vec<3>(1, 2, 3));
  write_text(path, "nOFF\n4\n1 0 0\n1 2 3 4\n");
  CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains("line 2: nOFF with vertices of dimension 4"),
                       std::runtime_error);
}

TEST_CASE("an OFF with no faces is a point set (with normals from NOFF), also for the input-shape loader") {
  TempDir dir;
  const std::string path = dir.file("points.off");
  std::string text = "NOFF\n40 0 0\n";
  std::vector<Vec<3>> expected;
  for (int i = 0; i < 40; ++i) {
    // A circle of radius 1 in the plane z = 0.5, with outward normals.
    const double a = 2.0 * 3.141592653589793 * i / 40.0;
    text += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0.5 " + std::to_string(std::cos(a)) +
            " " + std::to_string(std::sin(a)) + " 0\n";
  }
  write_text(path, text);
  CHECK_FALSE(is_mesh_file(path));
  const LoadedPointSet points = read_point_set(path);
  CHECK(points.dimension == 3);
  CHECK(points.has_normals);
  CHECK(points.points.size() == 40);
  SurfaceSampleOptions options;
  options.spacing = 0.1;
  options.normal_radius = 0.3;
  const SurfaceSamples samples = load_surface_samples(path, options);
  CHECK(samples.points.size() == 40);
  CHECK(samples.source.find("point set of 40 points with normals") != std::string::npos);

  // A mesh's vertices read as a point set carry no normals; the loader samples the mesh instead.
  write_text(path, "OFF\n8 6 0\n" + kCubeVertices + kCubeFaces);
  CHECK_FALSE(read_point_set(path).has_normals);
  const SurfaceSamples cube = load_surface_samples(path, options);
  CHECK(cube.source.find("mesh of 12 triangles") != std::string::npos);
  CHECK(cube.points.size() > 8);
}

TEST_CASE("broken OFF files are refused, naming the file and the line") {
  TempDir dir;
  const std::string path = dir.file("bad.off");
  struct Bad {
    const char* what;
    std::string text;
    std::string message;
  };
  const std::vector<Bad> files{
      {"empty", "", "bad.off: the file is empty"},
      {"only comments", "# nothing\n\n", "no OFF header"},
      {"not OFF", "ply\nformat ascii 1.0\n", "line 1: expected an OFF header such as 'OFF', 'NOFF' or 'COFF'"},
      {"binary", "OFF BINARY\n", "line 1: binary OFF is not supported"},
      {"no counts", "OFF\n", "the file ends before the header's vertex and face counts"},
      {"bad count", "OFF\n8 six 0\n", "line 2: 'six' is not a whole number"},
      {"negative count", "OFF\n-1 0 0\n", "line 2: negative counts"},
      {"too many header numbers", "OFF\n1 0 0 7\n", "too many numbers in the header"},
      {"absurd count", "OFF\n1000000000000000 0 0\n0 0 0\n",
       "line 2: truncated: the header promises 1000000000000000 vertices and 0 faces, more than a file of"},
      {"absurd face count", "OFF 1 99999999999 0\n0 0 0\n", "promises 1 vertices and 99999999999 faces"},
      {"truncated vertices", "OFF\n3 0 0\n0 0 0\n1 1 1\n", "truncated: the file ends after 2 of the 3 vertices"},
      {"truncated faces", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the file ends after 1 of the 2 faces"},
      {"vertex too short", "OFF\n2 0 0\n0 0 0\n1 1\n", "line 4: 2 values for a vertex; expected 3"},
      {"colour without COFF", "OFF\n1 0 0\n0 0 0 1 0 0\n", "line 3: 6 values for a vertex; expected 3 (colours need"},
      {"not a number", "OFF\n2 0 0\n0 0 0\n1 x 1\n", "line 4: 'x' is not a number"},
      {"face too short", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
       "line 6: the face promises 4 vertices but lists 3"},
      {"face index not a number", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n",
       "line 6: '2.5' is not a vertex index"},
      {"face too long", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 1 1 1 1\n", "line 6: 5 values after the face's"},
      {"data after the faces", "OFF\n1 0 0\n0 0 0\n1 1 1\n", "line 4: data after the last face"},
  };
  for (const Bad& file : files) {
    INFO(file.what);
    write_text(path, file.text);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains((path + ": ").c_str()), std::runtime_error);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains(file.message.c_str()), std::runtime_error);
  }
  // Faces are checked only by the mesh reader: a point set needs only the vertices.
  write_text(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  CHECK(read_point_set(path).points.size() == 3);
  CHECK_THROWS_WITH_AS(read_mesh(path), doctest::Contains("bad.off: line 6: vertex index 7 is out of range"),
                       std::runtime_error);
  write_text(path, "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n");
  CHECK_THROWS_WITH_AS(read_mesh(path), doctest::Contains("line 5: a vertex with a non-finite coordinate"),
                       std::runtime_error);
}
