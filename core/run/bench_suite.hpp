#pragma once
// The fixed benchmark suite of `amls bench`: the 2D vortex at 512^2 (exact and
// interpolated), one full step on 3D spheres of 50k, 200k and 1M points, a
// drag on spheres of 200k and 1M points resampled always or locally
// (core/run/drag_bench.hpp), and the Enright test at 128^3.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/run/deforming_surface.hpp"
#include "core/util/parallel_stopwatch.hpp"
#include "core/util/phase_times.hpp"

namespace amls {

struct BenchCase {
  std::string name;
  std::size_t points = 0;            // points entering the step (for a run: the largest point set)
  std::size_t points_processed = 0;  // points entering each step, summed over the steps
  PhaseTimes timings;                // normals, function, resample, deform, hash
  double peak_memory_mib = 0.0;      // peak resident memory during this case
  int threads = 1;
  // The whole case as the suite runs it (set-up, the timed loop, its
  // measures): wall time and the part of it inside parallel loops. Its
  // serial share on one thread bounds what more threads can gain.
  ParallelLap run;
  std::string result;                // the case's accuracy figure, in words
  // Named figures of the case, for the JSON report (the drag cases' step times and quality).
  std::vector<std::pair<std::string, double>> figures;
  double points_per_second() const {
    const double total = total_seconds(timings);
    return total > 0.0 ? static_cast<double>(points_processed) / total : 0.0;
  }
};

// One full step (normals, function, resample, deform by a small rigid rotation,
// hash) on a sphere of radius 0.3 sampled on the grid whose spacing gives about
// `points` points.
BenchCase bench_sphere_step(std::size_t points, int threads);

// A case of the suite, named before it runs so that callers can pick cases.
struct BenchSpec {
  std::string name;
  std::function<BenchCase()> run;
};

// The suite's cases in order, none run yet. Each measures its own run
// (BenchCase::run) on the thread that calls it.
std::vector<BenchSpec> bench_suite(int threads);

}  // namespace amls
