// Resampling a resample at the same h, on CGAL's sparse partial scans (the
// protocol of tools/fixed_point/run.sh, as `amls resample` runs it: widened
// supports, rims kept). Figures in docs/design.md, "Open surfaces".
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "real_data_files.hpp"

using namespace amls;
using amls::test::data_file;

namespace {

struct Counts {
  double first = 0.0, second = 0.0, third = 0.0;
};

// The point counts after one resample of the file at its own h and two more,
// each of the previous output, at that h.
Counts resample_three_times(const std::string& name) {
  PointSetResampling options;
  options.widen_support = true;
  options.threads = 2;
  ResampledPointSet<3> out = resample_point_set<3>(read_point_set(data_file(name)).points, options);
  options.spacing = out.grid.spacing();
  Counts counts;
  counts.first = static_cast<double>(out.points.size());
  out = resample_point_set<3>(std::move(out.points), options);
  counts.second = static_cast<double>(out.points.size());
  out = resample_point_set<3>(std::move(out.points), options);
  counts.third = static_cast<double>(out.points.size());
  return counts;
}

double change(double before, double after) { return std::abs(after - before) / before; }

}  // namespace

TEST_CASE("real data, fixed point: sparse partial scans gain at most 1.5 % a resample once resampled") {
  // hippo2's new points far from sparse old ones were taken for a sheet's
  // edge and left out, and the next resample put them back: +1.89 % and
  // +0.22 % before; +1.36 % and +0.03 % now.
  const Counts hippo = resample_three_times("points_3/hippo2.ply");
  CHECK(change(hippo.first, hippo.second) <= 0.015);
  CHECK(change(hippo.second, hippo.third) <= 0.015);
  // oni's second resample still gains +5.4 % (docs/design.md says where);
  // its third gained +2.15 % before, +1.11 % now.
  const Counts oni = resample_three_times("points_3/oni.ply");
  CHECK(change(oni.first, oni.second) <= 0.06);
  CHECK(change(oni.second, oni.third) <= 0.015);
}
