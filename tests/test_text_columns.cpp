#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/point_set_io.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

TEST_CASE("text columns: comma, semicolon, tab or space separators, with or without a header, in every extension") {
  TempDir dir;
  struct Case {
    const char* what;
    std::string text;
  };
  const std::vector<Case> cases{
      {"spaces", "1 2 3 0 0 1\n4 5 6 1 0 0\n"},
      {"tabs", "1\t2\t3\t0\t0\t1\n4\t5\t6\t1\t0\t0\n"},
      {"commas (CloudCompare's header)", "//X,Y,Z,Nx,Ny,Nz\n1,2,3,0,0,1\n4,5,6,1,0,0\n"},
      {"commas and spaces, a trailing comma", "x, y, z, nx, ny, nz\n1, 2, 3, 0, 0, 1,\n4, 5, 6, 1, 0, 0,\n"},
      {"semicolons, CRLF, a byte order mark", "\xEF\xBB\xBFX;Y;Z;NX;NY;NZ\r\n1;2;3;0;0;1\r\n4;5;6;1;0;0\r\n"},
      {"a header naming other columns and normal_x",
       "id red x y z normal_x normal_y normal_z label\n"
       "7 255 1 2 3 0 0 1 wall\n8 0 4 5 6 1 0 0 floor\n"},
      {"columns in another order", "nz,z,y,x,ny,nx\n1,3,2,1,0,0\n0,6,5,4,0,1\n"},
      {"comments and blank lines around a header",
       "# exported\n\nx y z nx ny nz\n# data\n1 2 3 0 0 1\n\n4 5 6 1 0 0\n"},
  };
  for (const char* extension : {".xyz", ".csv", ".txt", ".pwn", ".CSV"}) {
    for (const Case& c : cases) {
      INFO(c.what << " in " << extension);
      const std::string path = dir.file(std::string("points") + extension);
      write_text(path, c.text);
      const LoadedPointSet read = read_point_set(path);
      CHECK(read.warnings.empty());
      CHECK(read.dimension == 3);
      CHECK(read.has_normals);
      REQUIRE(read.points.size() == 2);
      CHECK(read.points.positions[0] == Vec<3>(1, 2, 3));
      CHECK(read.points.positions[1] == Vec<3>(4, 5, 6));
      CHECK(read.points.normals[0] == Vec<3>(0, 0, 1));
      CHECK(read.points.normals[1] == Vec<3>(1, 0, 0));
    }
  }
}

TEST_CASE("text columns: a header without z or normals, and headerless 2D columns") {
  TempDir dir;
  const std::string path = dir.file("set.csv");
  write_text(path, "x,y,z\n1,2,3\n4,5,6\n");
  LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == 3);
  CHECK_FALSE(read.has_normals);
  CHECK(read.points.size() == 2);

  write_text(path, "x;y;nx;ny\n1;2;0;1\n3;4;1;0\n");
  read = read_point_set(path);
  CHECK(read.dimension == 2);
  CHECK(read.has_normals);
  CHECK(read.points.normals[0] == Vec<3>(0, 1, 0));

  write_text(path, "1,2,0,1\n3,4,1,0\n");
  read = read_point_set(path);
  CHECK(read.dimension == 2);
  CHECK(read.has_normals);
  CHECK(read.points.positions[1] == Vec<3>(3, 4, 0));

  write_text(path, "x,y\n");  // a header and no points
  CHECK(read_point_set(path).points.empty());
}

TEST_CASE("broken text columns are refused, naming the file and the line") {
  TempDir dir;
  const std::string path = dir.file("bad.csv");
  struct Bad {
    const char* what;
    std::string text;
    std::string message;
  };
  const std::vector<Bad> files{
      {"empty field", "1,,3\n", "line 1: an empty value between two commas"},
      {"empty field, semicolons", "x;y;z\n1;2;3\n1; ;3\n", "line 3: an empty value between two semicolons"},
      {"header without x", "a,b,c\n1,2,3\n", "line 1: the header line names no 'x' and 'y' columns"},
      {"text where numbers are", "hello world\n", "(or, if it is not a header, 'hello' is not a number)"},
      {"header names a column twice", "x,y,z,X\n", "line 1: the header names 'x' twice"},
      {"some normals", "x,y,z,nx,ny\n", "line 1: the header names only some of the normal columns"},
      {"2D header with nz", "x,y,nx,ny,nz\n", "only some of the normal columns (nx ny for x y)"},
      {"five columns, no header", "1 2 3 4 5\n", "line 1: 5 values; expected x y z or x y z nx ny nz"},
      {"columns change", "x,y,z\n1,2,3\n1,2\n", "line 3: 2 values, but line 1 has 3"},
      {"separator changes", "1,2,3\n4 5 6\n", "line 2: 1 values, but line 1 has 3"},
      {"not a number after the header", "x y z\n1 2 3\n1 2 abc\n", "line 3: 'abc' is not a number"},
      {"a second header", "x y z\n1 2 3\nx y z\n", "line 3: 'x' is not a number"},
      {"a decimal comma", "1;2;3,5\n", "line 1: '3,5' is not a number"},
  };
  for (const Bad& file : files) {
    INFO(file.what);
    write_text(path, file.text);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains((path + ": ").c_str()), std::runtime_error);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains(file.message.c_str()), std::runtime_error);
  }
}
