#pragma once
// The drag benchmark of `amls bench` ("drag 200k", "drag 1M"): an editor's
// drag on a large surface. A sphere of radius 0.3 sampled by the grid whose
// spacing h gives about `points` points carries four handles on it: three
// fixed (the bottom and two on the equator) and one at the top, pulled
// outwards by `pull_h` h per step. Each step maps the points by the MLS map
// (rigid) that takes the handles from one step to the next and keeps the
// surface sampled by the chosen policy; only the step is timed.
//
// With `regions`, the handles are two region handles instead
// (core/deform/region_handle.hpp), reach h: the cap of the sphere's points
// within 0.05 of its bottom, pinned, and the cap within 0.05 of its top,
// moved outwards as the top handle is: what the same drag costs with regions.
//
// Quality after the run, as `amls deform` measures it: the nearest-neighbour
// spacing of the final points, and tracers (a denser sampling of the initial
// sphere carried by the same maps, never resampled) against the final
// surface: |F| at each tracer (in h, about its distance to the surface) and
// where F is undefined there (holes). The local policy maps its points from
// rest states rather than step by step, and its tracers follow the same maps
// exactly. Both end as a drag does: `always` resamples once more, `local`
// maps its points exactly.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/deform/region_handle.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"
#include "core/util/parallel_stopwatch.hpp"

namespace amls {

enum class DragResample {
  always,  // the paper's loop: the whole surface every step
  local,   // only where the sampling changed (core/run/local_deforming_surface.hpp)
};

const char* to_string(DragResample mode);

struct DragBenchConfig {
  std::size_t points = 200000;
  int threads = 1;
  std::size_t steps = 40;
  double pull_h = 0.5;          // the moving handle's step, in h
  std::size_t tracers = 50000;  // samples of the exact shape (0: no quality figures)
  DragResample resample = DragResample::always;
  bool regions = false;  // two region handles instead of the four point handles
};

struct DragBenchReport {
  DragBenchConfig config;
  double h = 0.0;
  std::size_t points_initial = 0;
  std::size_t points_final = 0;
  std::vector<double> step_seconds;  // per step: map, resampling and index
  // Per step, the process's CPU time (all threads): on a shared machine the
  // wall time grows with the other jobs' load; this much less.
  std::vector<double> step_cpu_seconds;
  std::vector<std::size_t> resampled;  // per step: points made by the resampler
  PhaseTimings timings;                // summed over the steps
  ParallelLap steps_parallel;          // the steps' wall time, and the part of it in parallel loops
  double median_ms() const;
  double max_ms() const;
  double cpu_median_ms() const;
  double mean_resampled() const;
  // With `regions`, the handles are two region handles instead
// (core/deform/region_handle.hpp), reach h: the cap of the sphere's points
// within 0.05 of its bottom, pinned, and the cap within 0.05 of its top,
// moved outwards as the top handle is: what the same drag costs with regions.
//
// Quality after the run (with tracers).
  SpacingStats spacing_h;
  double exact_to_surface_mean_h = 0.0;  // mean |F| / h at the tracers where F is defined
  double exact_to_surface_max_h = 0.0;
  std::size_t holes = 0;  // tracers where F is undefined
  std::size_t probes = 0;
  // Local only: its exact shape is the tracers mapped from rest states as its
  // points are (core/run/local_deforming_surface.hpp), not step by step as
  // always's: the largest distance between the two shapes, in h.
  double rest_map_drift_h = 0.0;
  // Local only: the drag's end. The last step leaves the points interpolated
  // on the lattice; the end of the drag maps them exactly
  // (LocalDeformingSurface::map_exactly, as the editor does once it waits),
  // and the quality above is measured after it. Its time, and the exact
  // shape to the surface before it (mean, max, in h).
  double finish_seconds = 0.0;
  double interpolated_to_surface_mean_h = 0.0;
  double interpolated_to_surface_max_h = 0.0;
};

// The drag's handles after `step` steps, for a sphere about `center` of `radius`.
std::vector<Vec<3>> drag_handles(const Vec<3>& center, double radius, double pull, std::size_t step);
// The drag's region handles after `step` steps: `caps` (bottom, top) at rest,
// the bottom pinned, the top moved outwards by `pull` a step.
std::vector<RegionHandle<3>> drag_regions(const std::array<std::shared_ptr<const PointRegion<3>>, 2>& caps, double pull,
                                          std::size_t step);

DragBenchReport run_drag_bench(const DragBenchConfig& config);

}  // namespace amls
