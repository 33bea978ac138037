#include "core/run/scene_run.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/deform/mls_deformation.hpp"
#include "core/run/growth_limit.hpp"
#include "core/run/local_deforming_surface.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/settle.hpp"
#include "core/surface/block_sample.hpp"
#include "core/surface/spacing_band.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

namespace {

void validate(const SceneRunOptions& options) {
  if (options.threads < 1) throw std::invalid_argument("--threads must be at least 1");
  if (!(options.tracers_per_point >= 1.0))
    throw std::invalid_argument("tracers per point must be at least 1, got " +
                                std::to_string(options.tracers_per_point));
}

// Undefined F at the probes, and the largest |F| / h at the others, on the pool.
template <int D>
void probe(const AmlsSurface<D>& surface, const std::vector<Vec<D>>& probes, ThreadPool& pool, std::size_t& holes,
           double& max_h) {
  struct Found {
    std::size_t holes = 0;
    double max_h = 0.0;
  };
  std::vector<OwnCacheLine<Found>> found(static_cast<std::size_t>(pool.threads()));
  pool.parallel_for(probes.size(), [&](std::size_t begin, std::size_t end, int block) {
    Found here;
    for (std::size_t i = begin; i < end; ++i) {
      const Evaluation<D> e = surface.evaluate(probes[i]);
      if (!e.defined) ++here.holes;
      else here.max_h = std::max(here.max_h, std::abs(e.value) / surface.grid().spacing());
    }
    Found& block_found = found[static_cast<std::size_t>(block)].value;
    block_found.holes += here.holes;
    block_found.max_h = std::max(block_found.max_h, here.max_h);
  });
  holes = 0;
  max_h = 0.0;
  for (const auto& f : found) {
    holes += f.value.holes;
    max_h = std::max(max_h, f.value.max_h);
  }
}

// The end's probes of a large run lie in blocks of this side (in h, or the
// margin below where wider), sampled as amls deform samples a frame's spacing
// (block_sample.hpp); the surface they are probed on is fitted to the points
// within kEndMargin Delta of those blocks only. F at a probe reads the points
// within Delta of it; their normals, the points within Delta of them; their
// rim flags and bias offsets, one Delta further: three Delta, and these
// points give F at the probes as all of them would (to rounding: the hash
// orders them otherwise). Blocks much wider than the margin keep the fitted
// points few: a surface's grow with the square of (side + 2 margin) / side
// (at 64 h and Delta = 3h, about 2 times the sampled blocks' own on a sphere,
// against 3 at 32 h), a curve's with its first power, where 32 h keeps enough
// blocks on a short curve.
template <int D>
constexpr double kEndBlock = D == 2 ? 32.0 : 64.0;
constexpr double kEndMargin = 3.0;

// One run of a scene (see scene_run.hpp): the loop over the history's steps,
// with the measurements each frame and the end take.
template <int D>
class SceneRunner {
 public:
  SceneRunner(const Scene<D>& scene, const SceneRunOptions& options, const FrameSink<D>& frames,
              const SceneProgress& progress)
      : scene_(scene), options_(options), frames_(frames), progress_(progress) {}

  SceneRunReport run(const FrameSink<D>& exact) {
    describe();
    start();
    SceneStepRecord record;
    if (!options_.resample) measure_frame(0, record);
    for (std::size_t k = 0; k < report_.steps_planned; ++k) {
      const HistoryStep<D> step = scene_.history.step(k);
      record.stage = step.stage;
      if (options_.resample && !settle_frame(k, record)) {
        report_.per_step.push_back(record);
        mark_broken(k, "the resampled point set is empty at step " + std::to_string(k) +
                           ": the surface has no zero crossing on the grid");
        break;
      }
      report_.per_step.push_back(record);
      deform(step);
      report_.steps = k + 1;
      record = SceneStepRecord{};
      record.stage = step.stage;
      if (!options_.resample) {
        probe_frame(k + 1, record);
        if (k + 1 == report_.steps_planned) report_.per_step.push_back(record);
      }
      const std::size_t n = points().size();
      if (progress_) progress_(k + 1, report_.steps_planned, n);
      if (grew_past_limit(n, report_.points_initial)) {
        mark_broken(k + 1, growth_breakdown(k + 1));
        break;
      }
    }
    if (options_.resample && !report_.broken) {
      // Under `local` the drag ends as in the editor: the points mapped exactly from the rest state.
      if (local_) {
        Stopwatch clock;
        local_->map_exactly();
        record.timings.deform += clock.lap();
      }
      settle_frame(report_.steps, record);  // an empty final point set is flagged below
      report_.timings += record.timings;
      report_.per_step.push_back(record);
    }
    finish(exact);
    return std::move(report_);
  }

 private:
  // The report's settings and plan.
  void describe() {
    report_.dimension = D;
    report_.scene = scene_.path;
    report_.name = scene_.name;
    report_.h = scene_.h();
    report_.radius_factor = scene_.radius_factor;
    report_.widen_support = scene_.widen_support;
    report_.variant = scene_.variant;
    report_.kind = scene_.kind;
    report_.alpha = scene_.alpha;
    report_.resample = options_.resample;
    report_.policy = options_.policy;
    report_.threads = options_.threads;
    report_.spacing_sample = options_.spacing_sample;
    report_.stages = scene_.history.stages.size();
    report_.steps_planned = scene_.history.total_steps();
    if (options_.max_steps > 0) report_.steps_planned = std::min(report_.steps_planned, options_.max_steps);
  }

  // The initial shape on its grid, the tracers and the probes among them.
  void start() {
    SceneShapeSamples<D> shape = sample_scene_shape(scene_, options_.tracers_per_point, options_.threads);
    report_.shape_source = shape.source;
    report_.warnings = shape.warnings;
    tracers_ = std::move(shape.tracers);
    report_.tracers = tracers_.size();
    probe_stride_ = static_cast<std::size_t>(std::max(1.0, std::round(options_.tracers_per_point / 4.0)));
    // A large run probes every k-th tracer, k as small as keeps the probes
    // to max_probes: F at a million probes costs a whole resample's normals.
    if (options_.max_probes > 0)
      probe_stride_ = std::max(probe_stride_, (tracers_.size() + options_.max_probes - 1) / options_.max_probes);
    report_.probes = (tracers_.size() + probe_stride_ - 1) / probe_stride_;

    const Grid<D> grid = resampling_grid(shape.points, scene_.h(), scene_.radius_factor);
    report_.grid_origin.template head<D>() = grid.origin();
    report_.points_initial = report_.points_min = report_.points_max = shape.points.size();
    const AmlsParameters parameters = scene_.parameters();
    if (options_.resample && options_.policy.kind == ResamplePolicy::Kind::local) {
      local_.emplace(grid, parameters, scene_.variant, options_.threads, options_.local);
      local_->set_points(std::move(shape.points));
      return;
    }
    surface_.emplace(grid, parameters, scene_.variant, options_.threads);
    surface_->set_points(std::move(shape.points));
  }

  const PointSet<D>& points() const { return local_ ? local_->points() : surface_->points(); }
  ThreadPool& pool() { return local_ ? local_->pool() : surface_->pool(); }

  std::vector<Vec<D>> probes() const { return every_kth(tracers_.positions, probe_stride_); }

  static std::vector<Vec<D>> every_kth(const std::vector<Vec<D>>& positions, std::size_t k) {
    std::vector<Vec<D>> out;
    out.reserve((positions.size() + k - 1) / k);
    for (std::size_t i = 0; i < positions.size(); i += k) out.push_back(positions[i]);
    return out;
  }

  // Measures the frame of `step` and hands it on. With resampling, only a
  // resample's frame counts in the run's spacing statistics: they describe
  // the resampler's points, not how far the deformation spread them since.
  void measure_frame(std::size_t step, SceneStepRecord& record) {
    Stopwatch clock;
    const PointSet<D>& points = this->points();
    record.step = step;
    record.points = points.size();
    const SpacingSummary spacing = spacing_summary(points, report_.h, options_.spacing_sample, pool());
    record.spacing_h = spacing.h;
    record.spacing_measured = spacing.measured;
    record.spacing_below = spacing.below;
    record.spacing_above = spacing.above;
    if (spacing.sampled()) ++report_.spacing_sampled_frames;
    const bool counted = !options_.resample || record.resampled || local_.has_value();
    if (counted) {
      report_.spacing_points += spacing.measured;
      report_.spacing_below += record.spacing_below;
      report_.spacing_above += record.spacing_above;
    }
    if (counted && points.size() >= 2) {
      report_.spacing_h.min =
          report_.frames_measured == 0 ? record.spacing_h.min : std::min(report_.spacing_h.min, record.spacing_h.min);
      report_.spacing_h.max = std::max(report_.spacing_h.max, record.spacing_h.max);
      medians_.push_back(record.spacing_h.median);
      ++report_.frames_measured;
    }
    report_.points_min = std::min(report_.points_min, points.size());
    report_.points_max = std::max(report_.points_max, points.size());
    report_.measure_seconds += clock.lap();
    if (frames_) frames_(step, points);
  }

  // With resampling, before step `step` (and after the last): resamples S(P)
  // if the policy asks, and makes the frame. False if the resample is empty.
  bool settle_frame(std::size_t step, SceneStepRecord& record) {
    if (local_) return local_frame(step, record);
    const Settling settled = *settle(*surface_, options_.policy, step, {}, held_regions(regions_));
    report_.quality_seconds += settled.quality_seconds;
    record.resampled = settled.resampled;
    if (record.resampled) {
      if (step == 0) report_.start_first_pass_points = settled.stats.first_pass_points;
      record.timings = settled.stats.timings;
      record.failed_normal_fits = settled.stats.normals.failed();
      ++report_.resamples;
    }
    measure_frame(step, record);
    return !surface_->points().empty();
  }

  // Under `local`, the frame of `step`: step 0 resamples the whole surface,
  // later frames are what the step before made (deformed, and resampled
  // where strained).
  bool local_frame(std::size_t step, SceneStepRecord& record) {
    if (step == 0) {
      const LocalStepStats stats = local_->resample_start();
      report_.start_first_pass_points = stats.first_pass_points;
      record.timings = stats.timings;
      local_resampled_ = true;
      local_failed_fits_ = stats.resample.normals.failed();
    }
    record.resampled = local_resampled_;
    record.failed_normal_fits = local_failed_fits_;
    if (record.resampled) ++report_.resamples;
    local_resampled_ = false;
    local_failed_fits_ = 0;
    measure_frame(step, record);
    return !points().empty();
  }

  // One step of the history: the points and the tracers deformed (under
  // `local`, the points resampled where strained too).
  void deform(const HistoryStep<D>& step) {
    const MlsDeformation<D> deformation(step.from, step.to, step.regions_from, step.regions_to, scene_.kind,
                                        scene_.alpha);
    regions_ = step.regions_to;
    if (local_) {
      const LocalStepStats stats = local_->step(deformation);
      report_.per_step.back().timings += stats.timings;
      local_resampled_ = stats.resample.flagged_cells > 0;
      local_failed_fits_ = stats.resample.normals.failed();
    } else {
      report_.per_step.back().timings += surface_->step(deformation, 0.0, 1.0, false).timings;
    }
    report_.timings += report_.per_step.back().timings;
    Stopwatch clock;
    // The tracers' rotations by the polar iteration, a few times cheaper than
    // an SVD per tracer and the same map to rounding: they only measure.
    MlsDeformation<D> tracer_map = deformation;
    tracer_map.use_polar_iteration(true);
    tracer_map.reset_fallbacks();
    tracer_map.apply(tracers_, pool());
    report_.tracer_seconds += clock.lap();
    report_.affine_fallbacks += deformation.fallbacks() + tracer_map.fallbacks();
  }

  // Without resampling, after step `step`: the surface probed for holes, and the frame.
  void probe_frame(std::size_t step, SceneStepRecord& record) {
    const NormalStats normals = surface_->refresh_normals();
    record.failed_normal_fits = normals.failed();
    Stopwatch clock;
    record.probed = true;
    probe(surface_->surface(), probes(), pool(), record.holes, record.probe_max_h);
    report_.measure_seconds += clock.lap();
    measure_frame(step, record);
    if (record.holes > 0)
      mark_broken(step, "the surface broke at step " + std::to_string(step) + ": F is undefined at " +
                            std::to_string(record.holes) + " of " + std::to_string(report_.probes) +
                            " probes of the exact shape (the points there are more than about 1.3 Delta apart)");
  }

  // The final surface against the exact shape, and the run's totals.
  void finish(const FrameSink<D>& exact) {
    const PointSet<D>& points = this->points();
    report_.points_final = points.size();
    Stopwatch clock;
    if (!points.empty()) {
      if (local_) {
        probe_final_local();
      } else {
        surface_->refresh_normals();
        probe(surface_->surface(), probes(), pool(), report_.final_holes, report_.final_probe_max_h);
      }
      // From a block sample of each set, at most about max_probes points
      // of it, against the other set's points near the sampled blocks: a
      // million nearest searches each way, or an index of a million points,
      // would cost more than the run's last steps.
      report_.distance_to_exact_h =
          nearest_distance_stats(points.positions, tracers_.positions, report_.h, options_.max_probes, pool());
      report_.exact_to_points_h =
          nearest_distance_stats(tracers_.positions, points.positions, report_.h, options_.max_probes, pool());
    }
    if (report_.final_holes > 0 && !options_.resample)
      mark_broken(report_.steps, "the final surface does not cover the exact shape: F is undefined at " +
                                     std::to_string(report_.final_holes) + " of " + std::to_string(report_.probes) +
                                     " probes");
    if (points.empty()) mark_broken(report_.steps, "the final point set is empty");
    report_.measure_seconds += clock.lap();
    if (!medians_.empty()) {
      std::sort(medians_.begin(), medians_.end());
      report_.spacing_h.median = medians_[medians_.size() / 2];
    }
    if (report_.affine_fallbacks > 0)
      report_.warnings.push_back("the affine fit fell back to similarity at " +
                                 std::to_string(report_.affine_fallbacks) +
                                 " point evaluations (nearly collinear or coplanar handles)");
    if (exact) exact(report_.steps, tracers_);
    report_.wall_seconds = wall_.lap();
  }

  // Under `local`, F at the final probes: every k-th tracer on the surface
  // of all the points, or past max_probes tracers, the tracers in sampled
  // blocks (about max_probes) on the surface of the points near them (kEndBlock<D>):
  // a fit of a million points' normals would cost more than a few of the run's steps.
  // Widened supports reach farther than the margin: all the points then.
  void probe_final_local() {
    if (options_.max_probes > 0 && tracers_.size() > options_.max_probes && !scene_.widen_support) {
      const double margin = kEndMargin * scene_.radius_factor * report_.h;
      const BlockSample<D> blocks(std::max(kEndBlock<D> * report_.h, margin),
                                  (tracers_.size() + options_.max_probes - 1) / options_.max_probes);
      std::vector<Vec<D>> probes;
      for (const auto& t : blocks.placed(tracers_.positions, 0.0, pool()))
        if (t.place == BlockPlace::inside) probes.push_back(tracers_.positions[t.id]);
      if (!probes.empty()) {
        const PointSet<D>& all = points();
        // The points within the margin of the sampled blocks, and any the block grid cannot key.
        const auto near_ids = blocks.placed(all.positions, margin, pool());
        PointSet<D> near;
        near.reserve(near_ids.size());
        for (const auto& p : near_ids) near.add(all.positions[p.id], all.normals[p.id]);
        report_.probes = probes.size();
        report_.final_probes_sampled = true;
        probe(local_->fitted_surface(std::move(near)), probes, pool(), report_.final_holes,
              report_.final_probe_max_h);
        return;
      }
    }
    probe(local_->fitted_surface(), probes(), pool(), report_.final_holes, report_.final_probe_max_h);
  }

  void mark_broken(std::size_t step, const std::string& why) {
    if (report_.broken) return;
    report_.broken = true;
    report_.broken_at_step = step;
    report_.status_reason = why;
  }

  const Scene<D>& scene_;
  const SceneRunOptions& options_;
  const FrameSink<D>& frames_;
  const SceneProgress& progress_;
  Stopwatch wall_;
  SceneRunReport report_;
  PointSet<D> tracers_;
  std::size_t probe_stride_ = 1;
  std::optional<DeformingSurface<D>> surface_;
  std::optional<LocalDeformingSurface<D>> local_;  // instead of surface_, under `local`
  // The region handles where the last step left them (none before the first):
  // a resample keeps the points they hold (core/geometry/held_regions.hpp).
  std::vector<RegionHandle<D>> regions_;
  // What the last local step did, for the next frame's record.
  bool local_resampled_ = false;
  std::size_t local_failed_fits_ = 0;
  std::vector<double> medians_;  // of the frames measured
};

}  // namespace

template <int D>
SceneRunReport run_scene(const Scene<D>& scene, const SceneRunOptions& options, const FrameSink<D>& frames,
                         const SceneProgress& progress, const FrameSink<D>& exact) {
  validate(options);
  scene.history.validate();
  return SceneRunner<D>(scene, options, frames, progress).run(exact);
}

template SceneRunReport run_scene<2>(const Scene<2>&, const SceneRunOptions&, const FrameSink<2>&, const SceneProgress&,
                                     const FrameSink<2>&);
template SceneRunReport run_scene<3>(const Scene<3>&, const SceneRunOptions&, const FrameSink<3>&, const SceneProgress&,
                                     const FrameSink<3>&);

}  // namespace amls
