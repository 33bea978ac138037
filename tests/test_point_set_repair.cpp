#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// One XYZ line, x y z nx ny nz, each value exact.
std::string line_of(const Vec<3>& p, const Vec<3>& n) {
  std::ostringstream out;
  out.precision(17);
  out << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << n.x() << ' ' << n.y() << ' ' << n.z() << '\n';
  return out.str();
}

bool has_warning(const LoadedPointSet& read, const std::string& text) {
  for (const std::string& warning : read.warnings)
    if (warning.find(text) != std::string::npos) return true;
  return false;
}

// The smallest cosine between each read normal and the sphere's outward normal at its point.
double worst_alignment(const LoadedPointSet& read, const Vec<3>& center) {
  double worst = 1.0;
  for (std::size_t i = 0; i < read.points.size(); ++i)
    worst = std::min(worst, read.points.normals[i].dot((read.points.positions[i] - center).normalized()));
  return worst;
}

}  // namespace

TEST_CASE("repairs: non-finite rows dropped, duplicates merged, zero and non-finite normals estimated, each counted") {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 0.5, 2000);
  std::string text;
  for (std::size_t i = 0; i < sphere.size(); ++i) {
    Vec<3> normal = sphere.normals[i];
    if (i % 400 == 7) normal = Vec<3>::Zero();  // 5 zero normals
    if (i == 100) normal = Vec<3>(kNan, 0, 0);  // and 2 non-finite ones
    if (i == 1500) normal = Vec<3>(0, kInf, 0);
    text += line_of(sphere.positions[i], normal);
    if (i == 10) text += line_of(Vec<3>(kNan, 1, 2), Vec<3>(0, 0, 1));  // line 12
    if (i == 20) text += line_of(Vec<3>(1, kInf, 2), Vec<3>(0, 0, 1));
  }
  // Exact duplicates: of a good point (its normal kept), and of a zero-normal point (which takes the copy's normal).
  text += line_of(sphere.positions[3], -sphere.normals[3]);
  text += line_of(sphere.positions[5], sphere.normals[5]);
  text += line_of(sphere.positions[407], sphere.normals[407]);

  TempDir dir;
  const std::string path = dir.file("scan.xyz");
  write_text(path, text);
  const LoadedPointSet read = read_point_set(path);
  CHECK(read.has_normals);
  REQUIRE(read.points.size() == 2000);
  CHECK(read.points.positions == sphere.positions);
  CHECK(read.warnings.size() == 3);
  CHECK(
      has_warning(read, path + ": 2 points with a non-finite coordinate were dropped (the first at line 12: nan 1 2)"));
  CHECK(has_warning(read, path + ": 3 points repeat the exact position of an earlier point and were merged into it "
                                 "(the first at line 2003)"));
  // Point 407's zero normal came back from its duplicate, so 6 were estimated.
  CHECK(has_warning(read, path + ": 6 points have a zero-length or non-finite normal (the first at line 8)"));
  CHECK(read.points.normals[3] == sphere.normals[3]);
  CHECK(read.points.normals[407] == sphere.normals[407]);
  for (const std::size_t i : {7, 807, 1207, 1607, 100, 1500}) {
    INFO("point " << i);
    CHECK(read.points.normals[i].norm() == doctest::Approx(1.0));
    CHECK(read.points.normals[i].dot(sphere.normals[i]) > 0.99);
  }
}

TEST_CASE("repairs: estimated normals do not depend on units or position, and a patch of them is oriented outward") {
  const PointSet<3> sphere = sample_sphere(Vec<3>(0.1, 0.2, 0.3), 1.0, 3000);
  // Every normal in the cap z > 0.8 is zero: its inner points have no neighbour with a normal.
  auto file_text = [&](double scale, const Vec<3>& shift) {
    std::string text;
    for (std::size_t i = 0; i < sphere.size(); ++i) {
      const bool cap = sphere.positions[i].z() > 0.3 + 0.8;
      text += line_of(scale * sphere.positions[i] + shift, cap ? Vec<3>::Zero() : sphere.normals[i]);
    }
    return text;
  };
  TempDir dir;
  write_text(dir.file("metres.xyz"), file_text(1.0, Vec<3>::Zero()));
  write_text(dir.file("millimetres_far.xyz"), file_text(1000.0, Vec<3>(1e7, -2e6, 3e5)));
  const LoadedPointSet metres = read_point_set(dir.file("metres.xyz"));
  const LoadedPointSet far = read_point_set(dir.file("millimetres_far.xyz"));
  REQUIRE(metres.points.size() == sphere.size());
  REQUIRE(far.points.size() == sphere.size());
  CHECK(has_warning(metres, "oriented as the fits agree with the normals on the whole"));
  CHECK(worst_alignment(metres, Vec<3>(0.1, 0.2, 0.3)) > 0.95);
  double largest_difference = 0.0;
  for (std::size_t i = 0; i < sphere.size(); ++i)
    largest_difference = std::max(largest_difference, (metres.points.normals[i] - far.points.normals[i]).norm());
  CHECK(largest_difference < 1e-6);
}

TEST_CASE("repairs in 2D: a zero normal on a circle is estimated in the plane") {
  const PointSet<2> circle = sample_circle(Vec<2>(0.5, 0.5), 0.25, 200);
  std::string text = "# amls dim 2\n";
  for (std::size_t i = 0; i < circle.size(); ++i) {
    const Vec<2> n = i == 50 ? Vec<2>::Zero() : circle.normals[i];
    text += line_of(Vec<3>(circle.positions[i].x(), circle.positions[i].y(), 0.0), Vec<3>(n.x(), n.y(), 0.0));
  }
  TempDir dir;
  write_text(dir.file("curve.xyz"), text);
  const LoadedPointSet read = read_point_set(dir.file("curve.xyz"));
  CHECK(read.dimension == 2);
  CHECK(read.warnings.size() == 1);
  CHECK(read.points.normals[50].z() == 0.0);
  CHECK(Vec<2>(read.points.normals[50].x(), read.points.normals[50].y()).dot(circle.normals[50]) > 0.99);
}

TEST_CASE("repairs in binary PLY: messages name the vertices by their index in the file, after drops and merges") {
  // A sphere as binary PLY with normals; vertex 3 is NaN, vertex 6 repeats vertex 5, vertex 9's normal is zero.
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 200);
  std::string bytes = "ply\nformat binary_big_endian 1.0\nelement vertex 202\n";
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"}) bytes += std::string("property double ") + name + "\n";
  bytes += "end_header\n";
  auto put = [&](const Vec<3>& p, const Vec<3>& n) {
    for (const double v : {p.x(), p.y(), p.z(), n.x(), n.y(), n.z()}) {
      char raw[8];
      std::memcpy(raw, &v, 8);
      if (std::endian::native != std::endian::big) std::reverse(raw, raw + 8);
      bytes.append(raw, 8);
    }
  };
  for (std::size_t i = 0, file_vertex = 0; i < sphere.size(); ++i, ++file_vertex) {
    if (file_vertex == 3) {
      put(Vec<3>(kNan, 0, 0), Vec<3>(0, 0, 1));
      ++file_vertex;
    }
    put(sphere.positions[i], file_vertex == 9 ? Vec<3>::Zero() : sphere.normals[i]);
    if (file_vertex == 5) {
      put(sphere.positions[i], sphere.normals[i]);
      ++file_vertex;
    }
  }
  TempDir dir;
  write_text(dir.file("sphere.ply"), bytes);
  const LoadedPointSet read = read_point_set(dir.file("sphere.ply"));
  REQUIRE(read.points.size() == 200);
  CHECK(read.points.positions == sphere.positions);
  CHECK(has_warning(read, "1 points with a non-finite coordinate were dropped (the first at vertex 3: nan 0 0)"));
  CHECK(has_warning(read,
                    "1 points repeat the exact position of an earlier point and were merged into it (the first "
                    "at vertex 6)"));
  CHECK(has_warning(read, "1 points have a zero-length or non-finite normal (the first at vertex 9)"));
  CHECK(read.points.normals[7].dot(sphere.normals[7]) > 0.99);  // file vertex 9
}

TEST_CASE("repairs in binary PLY: a NaN vertex is dropped, named by its index") {
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nend_header\n";
  for (const double v : {0.0, 0.0, 0.0, 1.0, kNan, 0.0, 1.0, 1.0, 0.0}) {
    char raw[8];
    std::memcpy(raw, &v, 8);
    if (std::endian::native == std::endian::big) std::reverse(raw, raw + 8);
    bytes.append(raw, 8);
  }
  TempDir dir;
  write_text(dir.file("nan.ply"), bytes);
  const LoadedPointSet read = read_point_set(dir.file("nan.ply"), 3);
  REQUIRE(read.points.size() == 2);
  CHECK(read.points.positions[1] == Vec<3>(1, 1, 0));
  REQUIRE(read.warnings.size() == 1);
  CHECK(read.warnings[0].find("1 points with a non-finite coordinate were dropped (the first at vertex 1: 1 nan 0)") !=
        std::string::npos);
}
