#include "core/run/scene_report_json.hpp"

#include <string>

#include "core/surface/spacing_band.hpp"

namespace amls {

namespace {

nlohmann::json spacing_json(const SpacingStats& s) {
  return {{"min", s.min}, {"median", s.median}, {"max", s.max}};
}

// The band's bounds as they appear in report keys and lines: "0.3h", "1.5h".
const std::string kBelow = spacing_band_text(kSpacingBandLow) + "h";
const std::string kAbove = spacing_band_text(kSpacingBandHigh) + "h";

nlohmann::json timings_json(const PhaseTimings& t) {
  return {{"normals", t.normals}, {"function", t.function}, {"resample", t.resample},
          {"deform", t.deform},   {"hash", t.hash},         {"total", t.total()}};
}

}  // namespace

nlohmann::json scene_report_json(const SceneRunReport& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  if (!r.name.empty()) j["name"] = r.name;
  j["dimension"] = r.dimension;
  j["shape"] = r.shape_source;
  j["h"] = r.h;
  j["grid_origin"] = {r.grid_origin.x(), r.grid_origin.y(), r.grid_origin.z()};
  j["radius_factor"] = r.radius_factor;
  // Only when on, as the scene writes it.
  if (r.widen_support) j["widen_support"] = true;
  j["variant"] = to_string(r.variant);
  j["deformation"] = {{"kind", to_string(r.kind)}, {"alpha", r.alpha}};
  j["resample"] = r.resample ? r.policy.to_string() : "off";
  j["resamples"] = r.resamples;
  j["threads"] = r.threads;
  j["stages"] = r.stages;
  j["steps"] = r.steps;
  j["steps_planned"] = r.steps_planned;
  j["status"] = r.broken ? "broken" : "ok";
  j["status_reason"] = r.status_reason;
  j["broken_at_step"] = r.broken ? nlohmann::json(r.broken_at_step) : nlohmann::json(nullptr);
  j["points_initial"] = r.points_initial;
  // The start's resample: 2 passes where the shape is sparser than h (DeformingSurface::resample_start).
  j["start_passes"] = r.start_first_pass_points > 0 ? 2 : 1;
  j["points_final"] = r.points_final;
  j["points_min"] = r.points_min;
  j["points_max"] = r.points_max;
  j["spacing_h"] = spacing_json(r.spacing_h);
  j["spacing_frames"] = r.frames_measured;
  // Frames larger than the sample are measured on an even sample of their points.
  j["spacing_sampled"] = {{"frames", r.spacing_sampled_frames}, {"sample", r.spacing_sample}};
  j["spacing_outside"] = {{"points", r.spacing_points},
                          {"below_" + kBelow, r.spacing_below},
                          {"above_" + kAbove, r.spacing_above},
                          {"fraction", r.spacing_points > 0 ? static_cast<double>(r.spacing_below + r.spacing_above) /
                                                                  static_cast<double>(r.spacing_points)
                                                            : 0.0}};
  j["tracers"] = r.tracers;
  j["probes"] = r.probes;
  j["distance_to_exact_h"] = {{"mean", r.distance_to_exact_h.mean}, {"max", r.distance_to_exact_h.max}};
  j["exact_to_points_h"] = {{"mean", r.exact_to_points_h.mean}, {"max", r.exact_to_points_h.max}};
  j["final_probe_holes"] = r.final_holes;
  j["final_probe_max_h"] = r.final_probe_max_h;
  j["final_probes_sampled"] = r.final_probes_sampled;
  nlohmann::json timings = timings_json(r.timings);
  timings["tracers"] = r.tracer_seconds;
  timings["measure"] = r.measure_seconds;
  timings["quality"] = r.quality_seconds;
  timings["wall"] = r.wall_seconds;
  j["timings_s"] = timings;
  j["affine_fallbacks"] = r.affine_fallbacks;
  j["warnings"] = r.warnings;
  nlohmann::json steps = nlohmann::json::array();
  for (const SceneStepRecord& s : r.per_step) {
    nlohmann::json step = {{"step", s.step},
                           {"stage", s.stage},
                           {"points", s.points},
                           {"resampled", s.resampled},
                           {"spacing_h", spacing_json(s.spacing_h)},
                           {"spacing_below_" + kBelow, s.spacing_below},
                           {"spacing_above_" + kAbove, s.spacing_above},
                           {"failed_normal_fits", s.failed_normal_fits},
                           {"timings_s", timings_json(s.timings)}};
    if (s.spacing_measured < s.points && s.spacing_measured > 0)
      step["spacing_sampled"] = {{"points", s.spacing_measured}, {"of", s.points}};
    if (s.probed) step["probe"] = {{"holes", s.holes}, {"max_h", s.probe_max_h}};
    steps.push_back(std::move(step));
  }
  j["per_step"] = std::move(steps);
  return j;
}

}  // namespace amls
