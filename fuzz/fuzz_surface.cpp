// Fuzz target: a small surface from fuzzed points and parameters, resampled
// once and deformed one step by fuzzed handles. The work is bounded by what
// the input can ask for: at most 48 points, grids of 8 to 48 cells, 1 to 4
// handles, parameters within their ranges (core/util/parameter_ranges.hpp) or,
// one time in eight, anywhere (to be refused). Refusals with
// std::invalid_argument are expected; a crash, a sanitizer report, a hang or
// a non-finite point in the result is a finding.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "core/deform/mls_deformation.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/util/parameter_ranges.hpp"
#include "fuzz/fuzz_support.hpp"

namespace {

using amls::fuzz::Bytes;

// A value of `range`, or (when the input says so) one of anything from -1e3 to 1e3.
double parameter(Bytes& in, const amls::ParameterRange& range) {
  if ((in.byte() & 7) == 0) return in.number(-1e3, 1e3);
  return in.number(range.min, std::min(range.max, 8.0 * range.min + 8.0));
}

template <int D>
amls::Vec<D> vec(Bytes& in, double lo, double hi) {
  amls::Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = in.number(lo, hi);
  return v;
}

template <int D>
void run(Bytes& in) {
  amls::AmlsParameters parameters;
  parameters.radius_factor = parameter(in, amls::ranges::kRadiusFactor);
  parameters.min_weight = parameter(in, amls::ranges::kMinWeight);
  parameters.orientation_filter = in.flag();
  parameters.bias_correction = in.flag();
  const int cells = static_cast<int>(in.count(8, 48));
  const amls::Variant variant = in.flag() ? amls::Variant::exact : amls::Variant::interpolated;
  amls::PointSet<D> points;
  const std::size_t n = in.count(1, 48);
  for (std::size_t i = 0; i < n; ++i) {
    amls::Vec<D> normal = vec<D>(in, -1.0, 1.0);
    if (normal.isZero(0.0)) normal[0] = 1.0;
    points.add(vec<D>(in, 0.2, 0.8), normal.normalized());
  }
  std::vector<amls::Vec<D>> from, to;
  const std::size_t handles = in.count(1, 4);
  for (std::size_t h = 0; h < handles; ++h) {
    from.push_back(vec<D>(in, 0.0, 1.0));
    to.push_back(from.back() + vec<D>(in, -0.1, 0.1));
  }
  const auto kind = static_cast<amls::MlsKind>(in.count(0, 2));
  const double alpha = parameter(in, amls::ranges::kAlpha);
  try {
    amls::DeformingSurface<D> surface(amls::Grid<D>::unit(cells), parameters, variant);
    surface.set_points(points);
    surface.resample_only();
    const amls::MlsDeformation<D> deformation(from, to, kind, alpha);
    surface.step(deformation, 0.0, 1.0);
    for (const amls::Vec<D>& p : surface.points().positions)
      if (!p.allFinite()) {
        std::fprintf(stderr, "a non-finite point after one step\n");
        std::abort();
      }
  } catch (const std::invalid_argument&) {
    // An out-of-range parameter or handle set, refused.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  if (in.flag()) {
    run<2>(in);
  } else {
    run<3>(in);
  }
  return 0;
}
