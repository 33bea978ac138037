#include <doctest/doctest.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/file_format.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/util/file_error.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
namespace fs = std::filesystem;

namespace {

using amls::test::file_bytes;
using amls::test::TempDir;

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  REQUIRE(out.good());
}


// Appends `value` as the bytes of a T in the given byte order.
template <typename T>
void put(std::string& out, T value, std::endian order) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof value);
  if (order != std::endian::native) std::reverse(bytes, bytes + sizeof value);
  out.append(bytes, sizeof value);
}

// Appends the small integer `value` as a PLY scalar of the named type.
void put_scalar(std::string& out, const std::string& type, int value, std::endian order) {
  if (type == "char" || type == "int8") return put(out, static_cast<std::int8_t>(value), order);
  if (type == "uchar" || type == "uint8") return put(out, static_cast<std::uint8_t>(value), order);
  if (type == "short" || type == "int16") return put(out, static_cast<std::int16_t>(value), order);
  if (type == "ushort" || type == "uint16") return put(out, static_cast<std::uint16_t>(value), order);
  if (type == "int" || type == "int32") return put(out, static_cast<std::int32_t>(value), order);
  if (type == "uint" || type == "uint32") return put(out, static_cast<std::uint32_t>(value), order);
  if (type == "float" || type == "float32") return put(out, static_cast<float>(value), order);
  if (type == "double" || type == "float64") return put(out, static_cast<double>(value), order);
  FAIL("no such type " << type);
}

// Appends `value` as a PLY scalar of the named type (integer types take it rounded toward zero).
void put_value(std::string& out, const std::string& type, double value, std::endian order) {
  if (type == "float") return put(out, static_cast<float>(value), order);
  if (type == "double") return put(out, value, order);
  put_scalar(out, type, static_cast<int>(value), order);
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

template <int D>
bool same_bits(const std::vector<Vec<D>>& a, const std::vector<Vec<D>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < D; ++k)
      if (!same_bits(a[i][k], b[i][k])) return false;
  return true;
}

// Values that a lossy writer would get wrong: no short decimal, extremes,
// subnormals, negative zero; then seeded random ones of every magnitude.
template <int D>
PointSet<D> awkward_points(bool with_normals, unsigned seed) {
  const std::vector<double> special{0.1,
                                    1.0 / 3.0,
                                    -2.0 / 7.0,
                                    1e300,
                                    -1e-300,
                                    5e-324,
                                    -0.0,
                                    std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::min(),
                                    123456789.123456789};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  PointSet<D> points;
  for (int i = 0; i < 40; ++i) {
    Vec<D> p, n;
    for (int k = 0; k < D; ++k) {
      const std::size_t s = static_cast<std::size_t>(i * D + k);
      p[k] = s < special.size() ? special[s] : u(rng) * std::pow(10.0, exponent(rng));
      n[k] = u(rng);
    }
    points.positions.push_back(p);
    if (with_normals) points.normals.push_back(n.normalized());
  }
  return points;
}

// A file that must be refused, and a part of the message that must say why.
struct BadFile {
  const char* what;
  std::string bytes;
  std::string message;
};

// Each file, written at `path`, makes read_point_set throw a message naming `path` and the problem.
void check_rejected(const std::string& path, const std::vector<BadFile>& files) {
  for (const BadFile& file : files) {
    INFO(file.what);
    write_file(path, file.bytes);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains((path + ": ").c_str()), std::runtime_error);
    CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains(file.message.c_str()), std::runtime_error);
  }
}

// Writes a D-dimensional set in `format`, reads it back, and checks that nothing changed.
template <int D>
void check_round_trip(const std::string& path, PointFileFormat format, bool with_normals) {
  const PointSet<D> set = awkward_points<D>(with_normals, D);
  write_point_set(path, set, format);
  const LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == D);
  CHECK(read.has_normals == with_normals);
  CHECK(read.warnings.empty());
  PointSet<D> back;
  if constexpr (D == 2) {
    back = to_2d(read.points);
  } else {
    back = read.points;
  }
  CHECK(same_bits<D>(back.positions, set.positions));
  if (with_normals) CHECK(same_bits<D>(back.normals, set.normals));
  if (!with_normals) CHECK(back.normals == std::vector<Vec<D>>(set.size(), Vec<D>::Zero()));
}

std::string extension_of(PointFileFormat format) { return format == PointFileFormat::xyz ? ".xyz" : ".ply"; }

const PointFileFormat kFormats[] = {PointFileFormat::ply_ascii, PointFileFormat::ply_binary_little_endian,
                                    PointFileFormat::ply_binary_big_endian, PointFileFormat::xyz};

// The smallest valid ASCII PLY header above `element vertex`, for the bad-file tables.
const std::string kAsciiHead = "ply\nformat ascii 1.0\n";
const std::string kXyzProperties = "property float x\nproperty float y\nproperty float z\n";
// An ASCII header for two vertices with normals; the vertices are lines 11 and 12.
const std::string kTwoOrientedVertices = kAsciiHead + "element vertex 2\n" + kXyzProperties +
                                         "property float nx\nproperty float ny\nproperty float nz\nend_header\n";

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

bool warned(const LoadedPointSet& read, const std::string& text) {
  return read.warnings.size() == 1 && read.warnings[0].find(text) != std::string::npos;
}

}  // namespace

TEST_CASE("every format round-trips 2D and 3D sets, with and without normals, bit for bit") {
  TempDir dir;
  for (const PointFileFormat format : kFormats) {
    for (const bool with_normals : {true, false}) {
      INFO("format " << to_string(format) << (with_normals ? " with normals" : " without normals"));
      const std::string path = dir.file(std::string("set") + extension_of(format));

      check_round_trip<3>(path, format, with_normals);
      check_round_trip<2>(path, format, with_normals);
    }
  }
  CHECK(dir.entries() == 2);  // set.ply and set.xyz: no temporary files left
}

TEST_CASE("a flat 3D set stays 3D and an empty set round-trips") {
  TempDir dir;
  for (const PointFileFormat format : kFormats) {
    INFO("format " << to_string(format));
    const std::string path = dir.file(std::string("flat") + extension_of(format));
    PointSet<3> flat;
    flat.add(Vec<3>(0.25, 0.5, 0.0), Vec<3>(1, 0, 0));
    flat.add(Vec<3>(0.75, 0.5, 0.0), Vec<3>(-1, 0, 0));
    write_point_set(path, flat, format);
    const LoadedPointSet read = read_point_set(path);
    CHECK(read.dimension == 3);  // the 'amls dim 3' comment wins over z = 0
    CHECK(read.warnings.empty());
    CHECK(read.points.positions == flat.positions);

    write_point_set(path, PointSet<2>{}, format);
    const LoadedPointSet empty = read_point_set(path);
    CHECK(empty.points.empty());
    CHECK(empty.dimension == 2);
    CHECK_FALSE(empty.has_normals);
  }
}

TEST_CASE("a resample's rim marks go into a PLY file and come back; other formats leave them out") {
  TempDir dir;
  PointSet<3> marked;
  marked.add(Vec<3>(0.25, 0.5, 0.125), Vec<3>(1, 0, 0));
  marked.add(Vec<3>(0.75, 0.5, 0.5), Vec<3>(-1, 0, 0), true);
  marked.add(Vec<3>(0.5, 0.25, 0.5), Vec<3>(0, 1, 0));
  REQUIRE(marked.rim == std::vector<std::uint8_t>{0, 1, 0});
  for (const PointFileFormat format : kFormats) {
    INFO("format " << to_string(format));
    const std::string path = dir.file(std::string("marked") + extension_of(format));
    write_point_set(path, marked, format);
    const LoadedPointSet read = read_point_set(path);
    CHECK(read.points.positions == marked.positions);
    const bool ply = extension_of(format) == std::string(".ply");
    CHECK(read.points.rim == (ply ? marked.rim : std::vector<std::uint8_t>{}));
    // 2D sets keep theirs too.
    PointSet<2> flat;
    flat.add(Vec<2>(0.25, 0.5), Vec<2>(0, 1), true);
    flat.add(Vec<2>(0.5, 0.5), Vec<2>(0, 1));
    write_point_set(path, flat, format);
    CHECK(read_point_set(path).points.rim == (ply ? flat.rim : std::vector<std::uint8_t>{}));
  }
  // Marks that are all 0 write no rim property: the file is the unmarked set's.
  const std::string plain = dir.file("plain.ply"), zeros = dir.file("zeros.ply");
  PointSet<3> unmarked = marked;
  unmarked.rim.clear();
  write_point_set(plain, unmarked, PointFileFormat::ply_binary_little_endian);
  unmarked.rim.assign(unmarked.size(), 0);
  write_point_set(zeros, unmarked, PointFileFormat::ply_binary_little_endian);
  CHECK(read_all(plain) == read_all(zeros));
  CHECK(read_point_set(plain).points.rim.empty());
  // A `rim` property that is no integer is someone else's: ignored.
  const std::string foreign = dir.file("foreign.ply");
  write_file(foreign, kAsciiHead + "element vertex 1\n" + kXyzProperties + "property float rim\nend_header\n0 0 0 1\n");
  CHECK(read_point_set(foreign).points.rim.empty());
}

TEST_CASE("the format follows the extension, in any case - other extensions are refused") {
  CHECK(format_from_extension("a/b.ply") == PointFileFormat::ply_binary_little_endian);
  CHECK(format_from_extension("B.PLY") == PointFileFormat::ply_binary_little_endian);
  CHECK(format_from_extension("c.Xyz") == PointFileFormat::xyz);
  CHECK_THROWS_WITH_AS(format_from_extension("points.txt"),
                       doctest::Contains("unknown point-set file extension '.txt'"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(format_from_extension("points"), doctest::Contains("no file extension"), std::invalid_argument);
  // Reading takes more formats than writing; a mesh-only or unknown extension is refused before the file is opened.
  CHECK_THROWS_WITH_AS(read_point_set("shape.OBJ"),
                       doctest::Contains("a .obj file holds a triangle mesh, not a point set (expected .ply, .off, .xyz, .pwn"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_point_set("points.dat"), doctest::Contains("'.dat'"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(read_point_set("points"), doctest::Contains("no file extension"), std::invalid_argument);
}

TEST_CASE("one rule for file extensions: lower-cased, and each reader's list") {
  CHECK(lower_extension("scans/Bunny.OFF") == ".off");
  CHECK(lower_extension("dir.v2/points") == "");
  CHECK(lower_extension("a.tar.GZ") == ".gz");
  CHECK(shape_file_format("x.Ply") == ShapeFileFormat::ply);
  CHECK(shape_file_format("x.off") == ShapeFileFormat::off);
  CHECK(shape_file_format("x.OBJ") == ShapeFileFormat::obj);
  for (const char* text : {"x.xyz", "x.PWN", "x.csv", "x.Txt"}) CHECK(shape_file_format(text) == ShapeFileFormat::xyz);
  CHECK(shape_file_format("x.STL") == ShapeFileFormat::stl);
  CHECK_FALSE(shape_file_format("x.3mf"));
  CHECK_FALSE(shape_file_format("x"));
  CHECK(is_point_set_file("x.off"));
  CHECK_FALSE(is_point_set_file("x.obj"));
  CHECK_FALSE(is_point_set_file("x.stl"));
  CHECK_FALSE(is_point_set_file("x.json"));
}

TEST_CASE("an ASCII PLY with CRLF lines, comments, normal_x names, a colour and a face list is read") {
  TempDir dir;
  const std::string path = dir.file("hand.ply");
  write_file(path,
             "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info scanner 7\r\n"
             "element vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
             "property uchar red\r\nproperty float normal_x\r\nproperty float normal_y\r\nproperty float normal_z\r\n"
             "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
             "0 0 1 255 0 0 1\r\n"
             "1.5 0 1 0 0 0 1\r\n"
             "\r\n"
             "0 -2.25 1 7 0 0 -1\r\n"
             "3 0 1 2\r\n");
  const LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == 3);
  CHECK(read.has_normals);
  CHECK(read.warnings.empty());
  REQUIRE(read.points.size() == 3);
  CHECK(read.points.positions[1] == Vec<3>(1.5, 0, 1));
  CHECK(read.points.positions[2] == Vec<3>(0, -2.25, 1));
  CHECK(read.points.normals[2] == Vec<3>(0, 0, -1));
}

TEST_CASE("a big-endian PLY with float32 coordinates, a colour and faces after the vertices is read") {
  TempDir dir;
  const std::string path = dir.file("hand_be.ply");
  std::string bytes = "ply\nformat binary_big_endian 1.0\nelement vertex 2\n" + kXyzProperties +
                      "property uchar red\nproperty float nx\nproperty float ny\nproperty float nz\n"
                      "element face 2\nproperty list uchar int vertex_indices\nproperty uchar flags\nend_header\n";
  const float vertices[2][7] = {{0.5f, 0.25f, -1.5f, 200, 0, 1, 0}, {0.1f, 2.0f, 3.0f, 9, 0, 0, 1}};
  for (const auto& v : vertices) {
    for (int k = 0; k < 3; ++k) put(bytes, v[k], std::endian::big);
    put(bytes, static_cast<std::uint8_t>(v[3]), std::endian::big);
    for (int k = 4; k < 7; ++k) put(bytes, v[k], std::endian::big);
  }
  for (const std::uint8_t corners : {std::uint8_t{3}, std::uint8_t{4}}) {
    put(bytes, corners, std::endian::big);
    for (int c = 0; c < corners; ++c) put(bytes, static_cast<std::int32_t>(c), std::endian::big);
    put(bytes, std::uint8_t{1}, std::endian::big);
  }
  write_file(path, bytes);
  const LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == 3);
  CHECK(read.has_normals);
  CHECK(read.warnings.empty());
  REQUIRE(read.points.size() == 2);
  CHECK(read.points.positions[0] == Vec<3>(0.5, 0.25, -1.5));
  CHECK(read.points.positions[1] == Vec<3>(double{0.1f}, 2.0, 3.0));  // float32 widened exactly
  CHECK(read.points.normals[0] == Vec<3>(0, 1, 0));
}

TEST_CASE("coordinates of every PLY scalar type are read, in ASCII and both binary orders") {
  TempDir dir;
  const std::string path = dir.file("types.ply");
  for (const std::string type : {"char", "uchar", "short", "ushort", "int", "uint", "float", "double", "int8", "uint8",
                                 "int16", "uint16", "int32", "uint32", "float32", "float64"}) {
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      INFO(type << " in " << format);
      // An element before the vertices, and a list inside the vertex element, both to be skipped.
      std::string bytes = "ply\nformat " + format +
                          " 1.0\nelement camera 1\nproperty double focal\nelement vertex 2\nproperty " + type +
                          " x\nproperty list uint16 " + type + " tags\nproperty " + type + " y\nproperty " + type +
                          " z\nend_header\n";
      const std::endian order = format == "binary_big_endian" ? std::endian::big : std::endian::little;
      if (format == "ascii") {
        bytes += "35\n1 2 7 8 2 3\n4 0 5 6\n";
      } else {
        put(bytes, 35.0, order);
        for (const std::vector<int>& v : {std::vector<int>{1, 2, 7, 8, 2, 3}, std::vector<int>{4, 0, 5, 6}}) {
          put_scalar(bytes, type, v[0], order);
          put(bytes, static_cast<std::uint16_t>(v[1]), order);
          for (std::size_t k = 2; k < v.size(); ++k) put_scalar(bytes, type, v[k], order);
        }
      }
      write_file(path, bytes);
      const LoadedPointSet read = read_point_set(path);
      REQUIRE(read.points.size() == 2);
      CHECK(read.points.positions[0] == Vec<3>(1, 2, 3));
      CHECK(read.points.positions[1] == Vec<3>(4, 5, 6));
      CHECK_FALSE(read.has_normals);
      CHECK(read.warnings.empty());
    }
  }
}

TEST_CASE(
    "PLY vertex properties of any type and other elements with lists are read past, in ASCII and both binary orders") {
  // As scanners and MeshLab write them: colours, a quality, a segment index and a list among x y z and the
  // normals, a point cloud's `element face 0`, and elements with lists before and after the vertices.
  struct Property {
    std::string type, name;
  };
  const std::vector<Property> vertex{
      {"float", "x"},        {"uchar", "red"}, {"uchar", "green"},       {"uchar", "blue"}, {"float", "y"},
      {"double", "quality"}, {"float", "z"},   {"int", "segment_index"}, {"float", "nx"},   {"ushort", "flags"},
      {"float", "ny"},       {"float", "nz"},  {"char", "alpha"}};
  const std::vector<std::vector<double>> values{{0.5, 255, 0, 12, -1.25, 0.125, 3, -7, 0, 65535, 0, 1, -128},
                                                {-2.5, 1, 2, 3, 4, 1e-3, -6, 2147483647, 1, 0, 0, 0, 127}};
  TempDir dir;
  const std::string path = dir.file("scan.ply");
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    INFO(format);
    const std::endian order = format == "binary_big_endian" ? std::endian::big : std::endian::little;
    std::string bytes = "ply\nformat " + format +
                        " 1.0\ncomment MeshLab-like\nelement material 1\nproperty list uchar double rgb\n"
                        "element vertex 2\n";
    for (const Property& p : vertex) bytes += "property " + p.type + " " + p.name + "\n";
    bytes +=
        "property list uchar int tags\nelement face 0\nproperty list uchar int vertex_indices\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    if (format == "ascii") {
      bytes += "3 0.1 0.2 0.3\n";
      bytes += "0.5 255 0 12 -1.25 0.125 3 -7 0 65535 0 1 -128 2 5 6\n";
      bytes += "-2.5 1 2 3 4 0.001 -6 2147483647 1 0 0 0 127 0\n";
      bytes += "0 1\n";
    } else {
      put(bytes, std::uint8_t{3}, order);
      for (const double v : {0.1, 0.2, 0.3}) put(bytes, v, order);
      for (std::size_t i = 0; i < values.size(); ++i) {
        for (std::size_t k = 0; k < vertex.size(); ++k) put_value(bytes, vertex[k].type, values[i][k], order);
        const std::vector<std::int32_t> tags = i == 0 ? std::vector<std::int32_t>{5, 6} : std::vector<std::int32_t>{};
        put(bytes, static_cast<std::uint8_t>(tags.size()), order);
        for (const std::int32_t t : tags) put(bytes, t, order);
      }
      put(bytes, std::int32_t{0}, order);
      put(bytes, std::int32_t{1}, order);
    }
    write_file(path, bytes);
    const LoadedPointSet read = read_point_set(path);
    CHECK(read.warnings.empty());
    CHECK(read.dimension == 3);
    CHECK(read.has_normals);
    REQUIRE(read.points.size() == 2);
    CHECK(read.points.positions[0] == Vec<3>(0.5, -1.25, 3));
    CHECK(read.points.positions[1] == Vec<3>(-2.5, 4, -6));
    CHECK(read.points.normals[0] == Vec<3>(0, 0, 1));
    CHECK(read.points.normals[1] == Vec<3>(1, 0, 0));
    CHECK_FALSE(is_mesh_file(path));  // `element face 0`: a point set
  }
}

TEST_CASE("XYZ files: CRLF, comments and blank lines - 3 or 6 columns in 3D, 2 or 4 in 2D") {
  TempDir dir;
  const std::string path = dir.file("hand.xyz");
  write_file(path, "# scanned\r\n\r\n1 2 3 0 0 2\r\n  4\t5 6 1 0 0  \r\n#last\r\n");
  LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == 3);
  CHECK(read.has_normals);
  REQUIRE(read.points.size() == 2);
  CHECK(read.points.positions[1] == Vec<3>(4, 5, 6));
  CHECK(read.points.normals[0] == Vec<3>(0, 0, 1));
  CHECK(warned(read, "were normalised"));  // the normal of length 2

  write_file(path, "1 2\n3 4\n");
  read = read_point_set(path);
  CHECK(read.dimension == 2);
  CHECK_FALSE(read.has_normals);
  CHECK(read.warnings.empty());
  CHECK(read.points.positions[1] == Vec<3>(3, 4, 0));

  write_file(path, "1 2 0 1\n3 4 -1 0\n");
  read = read_point_set(path);
  CHECK(read.dimension == 2);
  CHECK(read.has_normals);
  CHECK(read.points.normals[0] == Vec<3>(0, 1, 0));

  read = read_point_set(path, 3);  // the override keeps it 3D
  CHECK(read.dimension == 3);
}

TEST_CASE("the dimension: override, then the file's comment, then z = 0 everywhere, with a warning") {
  TempDir dir;
  const std::string path = dir.file("dim.ply");

  write_file(path, kTwoOrientedVertices + "0 0 0 1 0 0\n1 0 0 -1 0 0\n");
  LoadedPointSet read = read_point_set(path);
  CHECK(read.dimension == 2);
  CHECK(warned(read, "read as 2D"));
  read = read_point_set(path, 3);
  CHECK(read.dimension == 3);
  CHECK(read.warnings.empty());

  write_file(path, kTwoOrientedVertices + "0 0 0 1 0 0\n1 0 0 0 0 1\n");  // z = 0 but a normal leaves the plane
  read = read_point_set(path);
  CHECK(read.dimension == 3);
  CHECK(read.warnings.empty());

  write_file(path, kTwoOrientedVertices + "0 0 0 1 0 0\n1 0 0.5 -1 0 0\n");
  CHECK(read_point_set(path).dimension == 3);
  CHECK_THROWS_WITH_AS(read_point_set(path, 2),
                       doctest::Contains("line 12: z = 0.5, nz = 0, but the dimension is forced to 2"),
                       std::runtime_error);
  CHECK_THROWS_WITH_AS(read_point_set(path, 4), doctest::Contains("dimension must be 2 or 3"), std::invalid_argument);

  write_file(path, kAsciiHead + "comment amls dim 2\nelement vertex 1\n" + kXyzProperties + "end_header\n0 0 1\n");
  CHECK_THROWS_WITH_AS(read_point_set(path), doctest::Contains("z = 1, nz = 0, but the file says it holds a 2D set"),
                       std::runtime_error);
  CHECK(read_point_set(path, 3).dimension == 3);
}

TEST_CASE("normals: all zero means none, non-unit ones are normalised, a zero one among too few points is an error") {
  TempDir dir;
  const std::string path = dir.file("normals.ply");

  write_file(path, kTwoOrientedVertices + "0 0 1 0 0 0\n1 0 1 0 0 0\n");
  LoadedPointSet read = read_point_set(path);
  CHECK_FALSE(read.has_normals);
  CHECK(warned(read, "every normal is zero or not finite; read as a point set without normals"));

  write_file(path, kTwoOrientedVertices + "0 0 1 0 3 4\n1 0 1 0 0 1\n");
  read = read_point_set(path);
  CHECK(read.has_normals);
  CHECK((read.points.normals[0] - Vec<3>(0, 0.6, 0.8)).norm() < 1e-15);
  CHECK(warned(read, "1 normals were not of unit length and were normalised"));

  // Too few points to fit a normal from neighbours (see test_point_set_repair.cpp for the repair).
  write_file(path, kTwoOrientedVertices + "0 0 1 0 0 1\n1 0 1 0 0 0\n");
  CHECK_THROWS_WITH_AS(read_point_set(path),
                       doctest::Contains("line 12: zero-length or non-finite normal, and 2 points are too few"),
                       std::runtime_error);
}

TEST_CASE("bad PLY files throw a message naming the file and the problem") {
  TempDir dir;
  const std::string path = dir.file("bad.ply");
  const std::string vertex2 = "element vertex 2\n" + kXyzProperties;
  const std::string le = "ply\nformat binary_little_endian 1.0\n";
  std::string one_double_vertex;  // a whole binary vertex: x y z as doubles
  for (int k = 0; k < 3; ++k) put(one_double_vertex, 0.5, std::endian::little);
  const std::string double_xyz = "property double x\nproperty double y\nproperty double z\n";
  std::string bad_list = one_double_vertex;
  put(bad_list, std::int8_t{-1}, std::endian::little);

  check_rejected(
      path,
      {
          {"empty", "", "bad.ply: the file is empty"},
          {"no magic", "hello\nworld\n", "line 1: missing the 'ply' magic word"},
          {"magic with more", "plyx\n", "line 1: missing the 'ply' magic word"},
          {"unknown format", "ply\nformat binary_middle_endian 1.0\n", "line 2: unknown format 'binary_middle_endian'"},
          {"bad version", "ply\nformat ascii 2.0\n", "unsupported PLY version '2.0'"},
          {"no format", "ply\n" + vertex2 + "end_header\n", "no 'format' line"},
          {"no end_header", kAsciiHead + vertex2, "ends without 'end_header'"},
          {"unknown keyword", kAsciiHead + "elephant 3\n", "line 3: unknown header keyword 'elephant'"},
          {"long header line", "ply\n" + std::string(70000, 'a'), "line 2: longer than 65536 characters"},
          {"no vertex element", kAsciiHead + "element face 0\nend_header\n", "no 'vertex' element"},
          {"missing z", kAsciiHead + "element vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
           "no 'z' property"},
          {"partial normals", kAsciiHead + vertex2 + "property float nx\nend_header\n", "only some of the normal"},
          {"x as a list", kAsciiHead + "element vertex 0\nproperty list uchar float x\nend_header\n", "'x' is a list"},
          {"unknown type", kAsciiHead + "element vertex 1\nproperty float128 x\n", "unknown property type 'float128'"},
          {"float list length", kAsciiHead + "element face 1\nproperty list float int idx\n", "integer type"},
          {"property first", kAsciiHead + "property float x\n", "'property' before any 'element'"},
          {"duplicate property", kAsciiHead + vertex2 + "property float x\n", "two properties named 'x'"},
          {"duplicate element", kAsciiHead + vertex2 + vertex2, "a second element named 'vertex'"},
          {"bad dim comment", kAsciiHead + "comment amls dim 4\n", "line 3: expected 'amls dim 2' or 'amls dim 3'"},
          {"count not a number", kAsciiHead + "element vertex abc\n",
           "line 3: element 'vertex' count 'abc' is not a valid"},
          {"negative count", kAsciiHead + "element vertex -3\n", "line 3: element 'vertex' has a negative count (-3)"},
          {"count with more words", kAsciiHead + "element vertex 3 4\n", "expected 'element NAME COUNT'"},
          {"absurd ASCII count", kAsciiHead + "element vertex 1000000000000\n" + kXyzProperties + "end_header\n1 2 3\n",
           "truncated: the header promises 1000000000000 'vertex' items"},
          {"10^15 vertices in a small binary file",
           le + "element vertex 1000000000000000\n" + double_xyz + "end_header\n" + std::string(1000, '\0'),
           "truncated: the header promises 1000000000000000 'vertex' items of at least 24 bytes each, but only 1000"},
          {"absurd binary count",
           le + "element vertex 1000000000000\n" + kXyzProperties + "end_header\n" + one_double_vertex,
           "truncated: the header promises 1000000000000 'vertex' items"},
          {"absurd binary face count",
           le + "element vertex 1\n" + double_xyz +
               "element face 99999999999\nproperty list uchar int idx\nend_header\n" + one_double_vertex,
           "truncated: the header promises 99999999999 'face' items"},
          {"ASCII too few lines",
           kAsciiHead + "element vertex 3\n" + kXyzProperties + "end_header\n1.000 2.000 3.000\n4 5 6\n",
           "truncated: the file ends after 2 of the 3 'vertex' items"},
          {"ASCII extra value", kAsciiHead + vertex2 + "end_header\n1 2 3\n4 5 6 7\n",
           "line 9: 1 values too many for a 'vertex' item"},
          {"ASCII too few values", kAsciiHead + vertex2 + "end_header\n1.0 2.0 3.0\n4 5\n",
           "line 9: too few values for a 'vertex' item (none for 'z')"},
          {"ASCII not a number", kAsciiHead + vertex2 + "end_header\n1 2 3\n4 five 6\n",
           "line 9: 'five' is not a valid float for 'y'"},
          {"ASCII int out of range",
           kAsciiHead + "element vertex 1\nproperty uchar x\nproperty uchar y\nproperty uchar z\n"
                        "end_header\n1 300 2\n",
           "line 8: '300' is not a valid uchar for 'y'"},
          {"ASCII trailing data", kAsciiHead + vertex2 + "end_header\n1 2 3\n4 5 6\n7 8 9\n",
           "line 10: data after the last element"},
          {"ASCII negative list length",
           kAsciiHead + vertex2 + "element face 1\nproperty list uchar int idx\nend_header\n1 2 3\n4 5 6\n-1\n",
           "line 12: negative list length -1"},
          {"ASCII short list",
           kAsciiHead + vertex2 + "element face 1\nproperty list uchar int idx\nend_header\n1 2 3\n4 5 6\n3 0 1\n",
           "line 12: too few values for a 'face' item (list 'idx' promises 3)"},
          {"binary truncated vertex",
           le + "element vertex 2\n" + double_xyz + "end_header\n" + one_double_vertex + "abc", "truncated"},
          {"binary truncated list",
           le + "element vertex 1\n" + double_xyz + "element face 1\nproperty list uchar int idx\nend_header\n" +
               one_double_vertex + "\x03" + std::string(8, '\0'),
           "truncated: the file ends inside 'face' item 0 of the 1"},
          {"binary negative list length",
           le + "element vertex 1\n" + double_xyz + "property list char int idx\nend_header\n" + bad_list,
           "'vertex' item 0: negative list length -1 for 'idx'"},
      });
}

TEST_CASE("trailing bytes after a binary PLY's last element are reported") {
  TempDir dir;
  const std::string path = dir.file("tail.ply");
  std::string bytes =
      "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
      "property double z\nend_header\n";
  for (int k = 0; k < 3; ++k) put(bytes, 1.0, std::endian::big);
  write_file(path, bytes + "\n\n");
  const LoadedPointSet read = read_point_set(path);
  CHECK(read.points.positions[0] == Vec<3>(1, 1, 1));
  CHECK(warned(read, "2 bytes after the last element were ignored"));
}

TEST_CASE("bad XYZ files throw a message naming the file and the line") {
  TempDir dir;
  const std::string path = dir.file("bad.xyz");
  check_rejected(path, {
                           {"empty", "", "bad.xyz: the file is empty"},
                           {"five columns", "# head\n1 2 3 4 5\n", "line 2: 5 values; expected x y z"},
                           {"one column", "1\n2\n", "line 1: 1 values; expected"},
                           {"columns change", "1 2 3\n\n1 2\n", "line 3: 2 values, but line 1 has 3"},
                           {"not a number", "1 2 3\n1 2 abc\n", "line 2: 'abc' is not a number"},
                           {"2D points in a 3D file", "# amls dim 3\n1 2\n",
                            "line 2: the columns make 2D points (no z), but the file says 'amls dim 3'"},
                           {"bad dim comment", "#amls dim 7\n1 2 3\n", "line 1: expected 'amls dim 2' or 'amls dim 3'"},
                           {"2D comment, z set", "# amls dim 2\n1 2 0\n1 2 3\n",
                            "line 3: z = 3, nz = 0, but the file says it holds a 2D set"},
                       });
}

namespace {

// The system's errno comes with the message, so that callers (the Python module) can say which file error it was.
int file_error_of(const std::function<void()>& work) {
  try {
    work();
  } catch (const FileError& e) {
    return e.error();
  }
  return -1;
}

}  // namespace

TEST_CASE("missing files and directories are named in the error") {
  TempDir dir;
  CHECK_THROWS_WITH_AS(read_point_set(dir.file("none.ply")), doctest::Contains("none.ply: cannot open"),
                       std::runtime_error);
  CHECK(file_error_of([&] { read_point_set(dir.file("none.ply")); }) == ENOENT);
  fs::create_directory(dir.file("folder.xyz"));
  CHECK_THROWS_WITH_AS(read_point_set(dir.file("folder.xyz")), doctest::Contains("folder.xyz: is a directory"),
                       std::runtime_error);
  CHECK(file_error_of([&] { read_point_set(dir.file("folder.xyz")); }) == EISDIR);
  // A directory is named as one before its name's extension is judged.
  fs::create_directory(dir.file("folder"));
  CHECK(file_error_of([&] { read_point_set(dir.file("folder")); }) == EISDIR);
  CHECK(file_error_of([&] { read_mesh(dir.file("folder")); }) == EISDIR);
  PointSet<3> points;
  points.positions = {Vec<3>(0, 0, 0), Vec<3>(1, 0, 0)};
  points.normals = {Vec<3>::UnitZ(), Vec<3>::UnitZ()};
  CHECK(file_error_of([&] {
          write_point_set(dir.file("nowhere/s.ply"), points, PointFileFormat::ply_binary_little_endian);
        }) == ENOENT);
  CHECK(file_error_of([&] { write_point_set(dir.file("folder.xyz"), points, PointFileFormat::xyz); }) == EISDIR);
}

TEST_CASE("a failed write leaves the previous file intact and no temporary file behind") {
  TempDir dir;
  const std::string path = dir.file("keep.ply");
  PointSet<3> good;
  good.add(Vec<3>(1, 2, 3), Vec<3>(0, 0, 1));
  write_point_set(path, good, PointFileFormat::ply_ascii);
  const std::string before = file_bytes(path);

  PointSet<3> bad = good;
  bad.add(Vec<3>(std::nan(""), 0, 0), Vec<3>(0, 0, 1));
  CHECK_THROWS_WITH_AS(write_point_set(path, bad, PointFileFormat::ply_ascii),
                       doctest::Contains("keep.ply: point 1 has a non-finite coordinate"), std::invalid_argument);
  bad = good;
  bad.add(Vec<3>(0, 0, 0), Vec<3>(0, 0, 0));
  CHECK_THROWS_WITH_AS(write_point_set(path, bad, PointFileFormat::xyz),
                       doctest::Contains("point 1 has a zero normal while others have one"), std::invalid_argument);
  bad = good;
  bad.positions.push_back(Vec<3>(0, 0, 0));
  CHECK_THROWS_WITH_AS(write_point_set(path, bad, PointFileFormat::ply_binary_big_endian),
                       doctest::Contains("2 positions but 1 normals"), std::invalid_argument);
  CHECK(file_bytes(path) == before);

  fs::create_directory(dir.file("taken.ply"));
  CHECK_THROWS_WITH_AS(write_point_set(dir.file("taken.ply"), good, PointFileFormat::ply_binary_little_endian),
                       doctest::Contains("taken.ply: cannot replace the file"), std::runtime_error);
  CHECK_THROWS_WITH_AS(write_point_set(dir.file("no/such/dir/x.xyz"), good, PointFileFormat::xyz),
                       doctest::Contains("x.xyz: cannot create a temporary file"), std::runtime_error);
  CHECK(dir.entries() == 2);  // keep.ply and the taken.ply directory

  // A successful write replaces the old file.
  write_point_set(path, to_3d(PointSet<2>{}), PointFileFormat::ply_ascii);
  CHECK(read_point_set(path).points.empty());
}

TEST_CASE("to_2d refuses points off the plane z = 0 - to_3d puts them on it") {
  PointSet<2> flat;
  flat.add(Vec<2>(1, 2), Vec<2>(0, 1));
  const PointSet<3> lifted = to_3d(flat);
  CHECK(lifted.positions[0] == Vec<3>(1, 2, 0));
  CHECK(lifted.normals[0] == Vec<3>(0, 1, 0));
  CHECK(to_2d(lifted).positions == flat.positions);
  PointSet<3> off = lifted;
  off.add(Vec<3>(0, 0, 0), Vec<3>(0, 0, 1));
  CHECK_THROWS_WITH_AS(to_2d(off), doctest::Contains("point 1 is not a 2D point: z = 0, nz = 1"),
                       std::invalid_argument);
}
