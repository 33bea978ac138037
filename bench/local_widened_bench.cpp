// One local resample of a small region (core/resample/local_resampling.hpp)
// on a sphere sampled densely on its upper half and 4 x more sparsely on its
// lower half (tests/surface_fixtures.hpp), with widened supports and without,
// phase by phase: what a scan dragged under `local` pays at every resampling
// step. The region is the points within 2 region cells (a few cells
// flagged) or 8 (a drag's strained spot: hundreds) of a spot on the sphere:
// its north pole (dense, the sparse half out of reach), a point just above
// the equator (dense, the sparse half within reach) and its south pole
// (sparse).
//   amls_local_bench [dense points] [threads] [runs]
//   (defaults: 520000 2 5: 276k points; each figure the fastest of the runs)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "core/geometry/sample_spacing.hpp"
#include "core/resample/local_resampling.hpp"
#include "core/util/stopwatch.hpp"
#include "tests/surface_fixtures.hpp"

namespace {

// The fastest of the runs: the machine's other load only slows a run down.
double fastest(const std::vector<double>& values) { return *std::min_element(values.begin(), values.end()); }

}  // namespace

int main(int argc, char** argv) try {
  using namespace amls;
  const std::size_t dense = argc > 1 ? std::stoul(argv[1]) : 520000;
  const int threads = argc > 2 ? std::stoi(argv[2]) : 2;
  const int runs = argc > 3 ? std::stoi(argv[3]) : 5;
  const PointSet<3> input = test::half_sparse_sphere(dense);
  // The dense half's h, as the tests choose it.
  const double h = sample_spacing<3>(sample_sphere(Vec<3>::Zero(), 1.0, dense).positions).h;
  const Grid<3> grid(Vec<3>::Constant(-1.5), h);
  ThreadPool pool(threads);
  std::printf("%zu points, h = %.5g, %d threads, fastest of %d runs; times in ms\n", input.size(), h, threads, runs);
  std::printf("%-14s %6s %-8s %7s %7s %7s %7s %7s %7s %7s | %8s %8s %8s\n", "spot", "cells", "support", "rings",
              "radii", "fit", "F", "walk", "total", "wall", "flagged", "fitted", "new");
  struct Spot {
    const char* name;
    Vec<3> at;
  };
  for (const Spot& spot : {Spot{"north pole", Vec<3>(0.0, 0.0, 1.0)}, Spot{"above equator", Vec<3>(1.0, 0.0, 0.1)},
                           Spot{"south pole", Vec<3>(0.0, 0.0, -1.0)}})
    for (const double cells : {2.0, 8.0})
      for (const bool widen : {false, true}) {
        AmlsParameters parameters;
        parameters.widen_support = widen;
        LocalResampler<3> resampler(grid, parameters, Variant::exact);
        const Vec<3> at = spot.at.normalized();
        const double spread = cells * resampler.region_cell_size();
        std::vector<double> rings, radii, fit, function, walk, total, wall;
        LocalResampleStats stats;
        for (int run = 0; run < runs; ++run) {
          PointSet<3> points = input;
          std::vector<float> strain(points.size(), 0.0F);
          for (std::size_t i = 0; i < points.size(); ++i)
            if ((points.positions[i] - at).norm() < spread) strain[i] = 1.0F;
          Stopwatch clock;
          stats = resampler.resample(points, strain, pool);
          wall.push_back(1e3 * clock.lap());
          rings.push_back(1e3 * stats.rings_seconds);
          radii.push_back(1e3 * stats.radii_seconds);
          fit.push_back(1e3 * (stats.normals_seconds - stats.rings_seconds - stats.radii_seconds));
          function.push_back(1e3 * stats.function_seconds);
          walk.push_back(1e3 * stats.resample_seconds);
          total.push_back(1e3 * (stats.normals_seconds + stats.function_seconds + stats.resample_seconds));
        }
        std::printf("%-14s %6.0f %-8s %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f | %8zu %8zu %8zu\n", spot.name, cells,
                    widen ? "widened" : "one", fastest(rings), fastest(radii), fastest(fit), fastest(function),
                    fastest(walk), fastest(total), fastest(wall), stats.flagged_cells, stats.support, stats.inserted);
      }
  return EXIT_SUCCESS;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_local_bench: %s\n", e.what());
  return EXIT_FAILURE;
}
