#pragma once
// The accuracy tests of the paper's section 5: a shape carried by a velocity
// field that brings it back to where it started, resampled every dt, and
// compared with its initial self at the end. 2D: the single vortex (circle
// r = 0.15 at (0.5, 0.75), t in [0, 8]). 3D: Enright's field (sphere r = 0.15 at
// (0.35, 0.35, 0.35), t in [0, 3]).
#include <cstddef>
#include <functional>
#include <string>

#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"
#include "core/util/phase_times.hpp"
#include "core/resample/ray_resampler.hpp"
#include "core/resample/resample_policy.hpp"

namespace amls {

// How a flow test resamples: the paper's grid walk with exact or interpolated
// crossings (DeformingSurface), or the ray-tracing baseline of Gois et al.
// 2008 (RayTracingSurface).
enum class FlowVariant { exact, interpolated, raytrace };

const char* to_string(FlowVariant variant);
// Throws std::invalid_argument naming the accepted values.
FlowVariant parse_flow_variant(const std::string& name);

struct FlowTestConfig {
  int grid = 256;  // cells per unit length: h = 1 / grid
  FlowVariant variant = FlowVariant::exact;
  RaySettings ray;  // for FlowVariant::raytrace
  double radius_factor = 3.0;
  double min_weight = AmlsParameters{}.min_weight;
  bool bias_correction = AmlsParameters{}.bias_correction;  // 3D only; the ray-tracing baseline never has it
  bool keep_rims = AmlsParameters{}.keep_rims;
  double dt = 0.01;
  int substeps = 1;
  int threads = 1;
  ResamplePolicy resample;
  // --resample local: the summed strain above which a region is resampled
  // (LocalResampleOptions::strain_limit; docs/local-resampling.md says why
  // the flows need a lower one than a drag).
  double strain_limit = 0.05;
};

struct FlowTestReport {
  std::string test;  // "vortex" or "enright"
  int dimension = 2;
  FlowTestConfig config;
  std::size_t steps = 0;  // steps done (fewer than planned if the run broke)
  std::size_t resamples = 0;  // steps that resampled (all of them under --resample always; under local, somewhere)
  std::size_t steps_planned = 0;
  bool broken = false;
  std::string status_reason;
  std::size_t points_initial = 0;
  std::size_t points_max = 0;
  std::size_t points_final = 0;
  std::size_t points_processed = 0;  // points entering each step, summed over the steps
  SpacingStats spacing_h;  // of the final point set
  // Seconds per phase over the steps, the variant's own phases in its table's
  // order: normals, function, resample, deform, hash for the grid walk;
  // deform, remove_clusters, rebuild_tree, intersections, normals for ray tracing.
  PhaseTimes timings;
  // Seconds the policy spent deciding whether to resample: measuring the
  // sampling quality under `auto` (nothing else costs time). Not a phase of
  // the loop, so not in `timings`.
  double quality_seconds = 0.0;
  // Work done over the run: F evaluated at grid vertices (grid walk) or at the
  // samples along the rays (ray tracing), sign changes found (edges or
  // brackets), F evaluated by the root finder, candidates removed as clusters
  // (ray tracing), Pratt fits that failed.
  std::size_t vertex_evaluations = 0;
  std::size_t sample_evaluations = 0;
  std::size_t crossings = 0;
  std::size_t root_evaluations = 0;
  std::size_t removed_clusters = 0;
  std::size_t failed_normal_fits = 0;
  double peak_memory_mib = 0.0;
  double l1_error = 0.0;              // 2D
  double volume_loss = 0.0;           // 3D: (V0 - V) / V0
  double symmetric_difference = 0.0;  // 3D, absolute volume
  double relative_symmetric_difference = 0.0;  // 3D, divided by V0
};

// The report and the final point set (with its pseudo-normals as normals).
template <int D>
struct FlowTestRun {
  FlowTestReport report;
  PointSet<D> final_points;
};

// Called after every step with (steps done, steps planned, time, points).
using FlowProgress = std::function<void(std::size_t, std::size_t, double, std::size_t)>;

FlowTestRun<2> run_vortex_test(const FlowTestConfig& config, const FlowProgress& progress = {});
FlowTestRun<3> run_enright_test(const FlowTestConfig& config, const FlowProgress& progress = {});

}  // namespace amls
