#pragma once
// Runs a scene (`amls deform`): the initial shape is deformed through
// the scene's handle stages, one MLS deformation per step, with the paper's loop
// (section 4) - Update_Normals, Update_Function, Resample, Deform_Points, Hash -
// and measured against the exact deformed shape.
//
// The exact deformed shape phi(S0) is stood for by tracers: the initial shape
// sampled `tracers_per_point` times more densely (for a point-set file, the
// file's own points), carried by the same maps and never resampled.
//
// With resampling, the policy (core/resample/resample_policy.hpp) decides before step
// k whether S(P_k) is resampled into R_k; step k then deforms R_k (or P_k as
// it is) into P_{k+1}. After the last step it decides once more, for P_N: the
// final point set is R_N or P_N. Step 0 always resamples, and under `always`
// every step does (R_0 ... R_N). Frame k is R_k, or P_k where the policy did
// not resample; the spacing statistics take only the frames right after a
// resample, the points the resampler made (a skipped step's frame is recorded
// with its own spacing, but not counted in them).
// Without resampling, frame k is P_k, the initial points deformed k times.
// Under `local` (core/run/local_deforming_surface.hpp), step 0 resamples the
// whole surface and each step k deforms the points, then resamples them where
// the summed strain says the sampling changed: frame k + 1 is that point set,
// and every frame counts in the spacing statistics (each is what the loop
// carries on with; `resampled` says whether the step replaced any points).
//
// Breakdown (the paper's Fig. 2(b)): without resampling, the surface S(P) has
// broken at step k when it no longer covers the exact shape: F is undefined (no
// point of P reaches it with enough weight) at some probe - one tracer in every
// tracers_per_point / 4 (sparser beyond SceneRunOptions::max_probes). Every
// step is probed. With resampling the final surface is probed too (under
// `local` past max_probes tracers: the tracers in sampled blocks, on the
// surface of the points near them alone), but holes
// there are reported, not taken as a breakdown: the resampled surface cannot
// follow features of the exact shape thinner than the grid (a slot pinched to
// a fraction of h), and the distances say how much that loses. A resampling
// run breaks when its point set vanishes or grows past 20 times its start.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/resample/local_resampling.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/run/scene.hpp"
#include "core/run/scene_samples.hpp"

namespace amls {

struct SceneRunOptions {
  bool resample = true;  // false: deform the initial points only (`--no-resample`)
  ResamplePolicy policy;  // when resampling, which steps resample
  LocalResampleOptions local;  // under `local`
  int threads = 1;
  double tracers_per_point = 50.0;
  std::size_t max_steps = 0;  // stop after this many steps (0: the whole history)
  // A frame of more points has its spacing measured on an even sample of
  // this many (core/surface/metrics.hpp, spacing_summary): measuring every
  // point of a million-point frame costs more than the step that made it.
  static constexpr std::size_t kDefaultSpacingSample = 20000;
  std::size_t spacing_sample = kDefaultSpacingSample;
  // Probes: one tracer in every tracers_per_point / 4, and at most this many
  // (0: no limit). The end's two-way distances (final points to tracers and
  // back) measure from about this many of each set too, the points of
  // blocks sampled as a frame's spacing sample is (metrics.hpp).
  std::size_t max_probes = 100000;
};

struct SceneStepRecord {
  std::size_t step = 0;  // the state after this many steps
  std::size_t stage = 0;
  std::size_t points = 0;  // in the frame of this step
  bool resampled = false;  // the frame is a resample's (R_k), made in this record's step
  SpacingStats spacing_h;  // of the frame's points, in units of h
  std::size_t spacing_measured = 0;  // the points spacing_h is of: all, or a sample of a large frame
  std::size_t spacing_below = 0;  // points whose nearest neighbour is nearer than 0.3 h
  std::size_t spacing_above = 0;  // ... farther than 1.5 h
  PhaseTimings timings;    // of the work that made the frame (resample) and of the deformation after it
  std::size_t failed_normal_fits = 0;
  // Probes (without resampling, every step): where F is undefined, and the
  // largest |F| in units of h at the others (about the distance from the exact
  // shape to S(P)).
  bool probed = false;
  std::size_t holes = 0;
  double probe_max_h = 0.0;
};

struct SceneRunReport {
  int dimension = 2;
  std::string scene;  // its path
  std::string name;
  std::string shape_source;  // how the initial shape was made
  double h = 0.0;
  Vec<3> grid_origin = Vec<3>::Zero();
  double radius_factor = 3.0;
  bool widen_support = false;  // the scene's (AmlsParameters::widen_support)
  Variant variant = Variant::exact;
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
  bool resample = true;
  ResamplePolicy policy;  // when resampling
  int threads = 1;

  std::size_t stages = 0;
  std::size_t steps = 0;  // done
  std::size_t steps_planned = 0;
  std::size_t resamples = 0;  // R_k made, the final R_N included (steps + 1 under `always`); local: steps that resampled somewhere, and step 0
  bool broken = false;
  std::string status_reason;
  std::size_t broken_at_step = 0;  // the first step at which the surface was found broken (if broken)

  std::size_t points_initial = 0;  // of the initial shape's samples
  // The start's resample made a second pass (a shape sparser than h,
  // DeformingSurface::resample_start): its first pass's points; else 0.
  std::size_t start_first_pass_points = 0;
  std::size_t points_final = 0;
  std::size_t points_min = 0;
  std::size_t points_max = 0;
  std::size_t tracers = 0;
  std::size_t probes = 0;

  // Over the frames measured (with resampling, those right after a resample;
  // without, every frame): the least minimum, the median of the medians, the
  // largest maximum.
  SpacingStats spacing_h;
  std::size_t frames_measured = 0;
  std::size_t spacing_sample = 0;          // SceneRunOptions::spacing_sample
  std::size_t spacing_sampled_frames = 0;  // frames (counted or not) measured on a sample of their points
  // Over the same frames: points measured, and those with a nearest neighbour
  // nearer than 0.3 h or farther than 1.5 h (the band a well-sampled surface keeps).
  std::size_t spacing_points = 0;
  std::size_t spacing_below = 0;
  std::size_t spacing_above = 0;
  // Final point set -> nearest tracer, and tracer -> nearest final point (the
  // second also sees parts of the exact shape that the points lost).
  DistanceStats distance_to_exact_h;
  DistanceStats exact_to_points_h;
  std::size_t final_holes = 0;  // probes where the final F is undefined
  bool final_probes_sampled = false;  // the final probes are the tracers of sampled blocks (scene_run.cpp)
  double final_probe_max_h = 0.0;

  PhaseTimings timings;  // the surface's own work, as in the flow tests
  double tracer_seconds = 0.0;
  double measure_seconds = 0.0;  // spacing, probes and distances
  double quality_seconds = 0.0;  // the policy's sampling-quality checks (`auto`; not in `timings`)
  double wall_seconds = 0.0;
  std::size_t affine_fallbacks = 0;
  std::vector<std::string> warnings;
  std::vector<SceneStepRecord> per_step;
};

// Called with (step, points) for every frame: step 0 is the start.
template <int D>
using FrameSink = std::function<void(std::size_t, const PointSet<D>&)>;
// Called after every step with (steps done, steps planned, points).
using SceneProgress = std::function<void(std::size_t, std::size_t, std::size_t)>;

// `exact`, if set, is called once at the end with (steps, tracers): the exact deformed shape.
template <int D>
SceneRunReport run_scene(const Scene<D>& scene, const SceneRunOptions& options, const FrameSink<D>& frames = {},
                         const SceneProgress& progress = {}, const FrameSink<D>& exact = {});

extern template SceneRunReport run_scene<2>(const Scene<2>&, const SceneRunOptions&, const FrameSink<2>&,
                                            const SceneProgress&, const FrameSink<2>&);
extern template SceneRunReport run_scene<3>(const Scene<3>&, const SceneRunOptions&, const FrameSink<3>&,
                                            const SceneProgress&, const FrameSink<3>&);

}  // namespace amls
