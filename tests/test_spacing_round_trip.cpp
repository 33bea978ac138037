// The rule that chooses h is a fixed point on amls's own output: an output
// made at h, read back, gives h again - recorded in the file, or, without the
// record, from the grid lines its points lie on - while a raw scan keeps the
// 4th-neighour rule (core/geometry/sample_spacing.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "tests/temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;
using amls::test::write_text;

namespace {

// The part of a unit sphere's samples above z = 0.3: an open cap.
PointSet<3> sample_cap(std::size_t sphere_points) {
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, sphere_points);
  PointSet<3> cap;
  for (std::size_t i = 0; i < sphere.size(); ++i)
    if (sphere.positions[i].z() > 0.3) cap.add(sphere.positions[i], sphere.normals[i]);
  return cap;
}

template <int D>
ResampledPointSet<D> resampled_at(const PointSet<D>& points, double h) {
  PointSetResampling options;
  options.spacing = h;
  options.widen_support = true;  // as `amls resample` does
  return resample_point_set(points, options);
}

// What `amls resample` does with no spacing option: h by the rule, the file's record first.
template <int D>
ResampledPointSet<D> resampled_by_default(const LoadedPointSet& loaded) {
  PointSetResampling options;
  options.recorded_spacing = loaded.spacing;
  options.widen_support = true;
  return resample_point_set(from_3d<D>(loaded.points), options);
}

// Reading back `made` (made at h) from `path`, with and without the record.
// `neighbour_ratio`: what the 4th-neighbour rule alone gives on it, in h.
// `closed`: the surface has no rim, so resampling it again at h gives back its
// points within 2 % (past an open rim the resampling grows the surface, at any h).
template <int D>
void check_round_trip(const PointSet<D>& made, double h, const std::string& path, PointFileFormat format,
                      double neighbour_ratio, bool closed) {
  CAPTURE(path);
  write_point_set(path, made, format, h);
  const LoadedPointSet recorded = read_point_set(path);
  CHECK(recorded.spacing == h);
  const SampleSpacing by_record = sample_spacing<D>(from_3d<D>(recorded.points.positions), recorded.spacing);
  CHECK(by_record.rule == SpacingRule::recorded);
  CHECK(by_record.h == h);
  const ResampledPointSet<D> again = resampled_by_default<D>(recorded);
  CHECK(again.grid.spacing() == h);
  if (closed)
    CHECK(static_cast<double>(again.points.size()) ==
          doctest::Approx(static_cast<double>(made.size())).epsilon(0.02));

  // Without the record (a file from before it, or through another program): the grid lines.
  write_point_set(path, made, format);
  const LoadedPointSet bare = read_point_set(path);
  CHECK(bare.spacing == 0.0);
  const SampleSpacing by_lines = sample_spacing<D>(from_3d<D>(bare.points.positions));
  CHECK(by_lines.rule == SpacingRule::grid_lines);
  CHECK(by_lines.grid_lines.share >= kGridLineShare);
  CHECK(by_lines.h == doctest::Approx(h).epsilon(1e-9));
  CHECK(by_lines.neighbour_h / h == doctest::Approx(neighbour_ratio).epsilon(0.05));
  const ResampledPointSet<D> from_lines = resampled_by_default<D>(bare);
  CHECK(from_lines.grid.spacing() == doctest::Approx(h).epsilon(1e-9));
  if (closed)
    CHECK(static_cast<double>(from_lines.points.size()) ==
          doctest::Approx(static_cast<double>(made.size())).epsilon(0.02));
}

}  // namespace

TEST_CASE("an output made at h and read back gives h again, in PLY and XYZ, with and without the record") {
  TempDir dir;
  SUBCASE("a sphere") {
    const double h = 0.05;
    const ResampledPointSet<3> made = resampled_at(sample_sphere(Vec<3>(0.1, -0.2, 0.3), 1.0, 6000), h);
    // On a surface the neighbours lie about 1.16 h apart: the 4th-neighbour rule gives 0.58 h.
    check_round_trip<3>(made.points, h, dir.file("sphere.ply"), PointFileFormat::ply_binary_little_endian, 0.58, true);
    check_round_trip<3>(made.points, h, dir.file("sphere.xyz"), PointFileFormat::xyz, 0.58, true);
  }
  SUBCASE("an open cap") {
    const double h = 0.04;
    const ResampledPointSet<3> made = resampled_at(sample_cap(12000), h);
    check_round_trip<3>(made.points, h, dir.file("cap.ply"), PointFileFormat::ply_ascii, 0.58, false);
    check_round_trip<3>(made.points, h, dir.file("cap.xyz"), PointFileFormat::xyz, 0.58, false);
  }
  SUBCASE("a circle, 2D") {
    const double h = 0.02;
    const ResampledPointSet<2> made = resampled_at(sample_circle(Vec<2>(0.43, 0.51), 0.27, 300), h);
    // On a curve the 4th neighbour is two steps of about 1.05 h away: the rule gives 1.1 h.
    check_round_trip<2>(made.points, h, dir.file("circle.ply"), PointFileFormat::ply_binary_big_endian, 1.1, true);
    check_round_trip<2>(made.points, h, dir.file("circle.xyz"), PointFileFormat::xyz, 1.1, true);
  }
}

TEST_CASE("raw samples keep the 4th-neighbour rule: scattered, quantised, and on scan lines") {
  SUBCASE("scattered on a sphere") {
    const PointSet<3> scan = sample_sphere(Vec<3>::Zero(), 1.0, 5000);
    const SampleSpacing s = sample_spacing<3>(scan.positions);
    CHECK(s.rule == SpacingRule::neighbours);
    CHECK(s.h == s.kth_median / kSpacingNeighbourDivisor);
    CHECK(s.grid_lines.share < 0.01);
  }
  SUBCASE("quantised: every coordinate rounded to 1/64 of the spacing, so that values repeat on every axis") {
    PointSet<3> scan = sample_sphere(Vec<3>::Zero(), 1.0, 20000);
    const double quantum = sample_spacing<3>(scan.positions).h / 64.0;
    for (Vec<3>& p : scan.positions) p = (p / quantum).array().round() * quantum;
    const SampleSpacing s = sample_spacing<3>(scan.positions);
    CHECK(s.rule == SpacingRule::neighbours);
    CHECK(s.grid_lines.share < 0.5);
  }
  SUBCASE("scan lines on a lattice in the plane z = 0: every coordinate shared, none free") {
    std::vector<Vec<3>> lines;
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 100; ++i) lines.emplace_back(i * 0.01, j * 0.1, 0.0);
    const SampleSpacing s = sample_spacing<3>(lines);
    CHECK(s.rule == SpacingRule::neighbours);
    CHECK(s.grid_lines.share == 0.0);
    CHECK(s.h == doctest::Approx(0.01));
  }
}

TEST_CASE("grid lines: shared coordinates counted per point, and the step between them") {
  // Points on the lines x = 0.1 k of the plane, at irrational y: one shared coordinate each.
  std::vector<Vec<2>> points;
  for (int k = 0; k < 20; ++k)
    for (int m = 0; m < 3; ++m) points.emplace_back(0.1 * k, std::sqrt(2.0) * (k + 20 * m) / 7.0);
  GridLines lines = grid_lines_of<2>(points);
  CHECK(lines.share == 1.0);
  CHECK(lines.step == doctest::Approx(0.1));
  points.emplace_back(0.05, 0.333);  // a point on no line
  lines = grid_lines_of<2>(points);
  CHECK(lines.share == doctest::Approx(60.0 / 61.0));
  CHECK(grid_lines_of<2>(std::vector<Vec<2>>{}).share == 0.0);
}

TEST_CASE("a recorded spacing: written as 'amls spacing', read back exactly, malformed ones refused") {
  TempDir dir;
  const PointSet<3> points = sample_sphere(Vec<3>::Zero(), 1.0, 50);
  write_point_set(dir.file("a.xyz"), points, PointFileFormat::xyz, 0.1 / 3.0);
  CHECK(read_point_set(dir.file("a.xyz")).spacing == 0.1 / 3.0);
  CHECK_THROWS_WITH_AS(write_point_set(dir.file("b.xyz"), points, PointFileFormat::xyz, std::nan("")),
                       doctest::Contains("the spacing to record"), std::invalid_argument);
  const std::pair<std::string, std::string> bad[] = {
      {"# amls spacing -1\n0 0 0\n", "line 1: expected 'amls spacing H' with H a positive number"},
      {"# amls spacing\n0 0 0\n", "line 1: expected 'amls spacing H'"},
      {"# amls spacing 0.1 0.2\n0 0 0\n", "line 1: expected 'amls spacing H'"},
      {"# amls spacing 0.1\n# amls spacing 0.2\n0 0 0\n", "line 2: conflicting 'amls spacing' comments"},
  };
  for (const auto& [text, message] : bad) {
    CAPTURE(text);
    write_text(dir.file("bad.xyz"), text);
    CHECK_THROWS_WITH_AS(read_point_set(dir.file("bad.xyz")), doctest::Contains(message.c_str()), std::runtime_error);
  }
  write_text(dir.file("c.ply"),
             "ply\nformat ascii 1.0\ncomment amls spacing 0.25\nelement vertex 1\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n1 2 3\n");
  CHECK(read_point_set(dir.file("c.ply")).spacing == 0.25);
  CHECK_THROWS_WITH_AS(sample_spacing<3>(points.positions, -1.0), doctest::Contains("recorded spacing"),
                       std::invalid_argument);
}
