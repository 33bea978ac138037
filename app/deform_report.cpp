#include "app/deform_report.hpp"

#include <cstdio>
#include <ostream>
#include <string>

#include "core/surface/spacing_band.hpp"

namespace amls::app {

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

nlohmann::json to_json(const SceneRunReport& r) {
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

void print_summary(std::ostream& out, const SceneRunReport& r) {
  char line[512];
  const bool local = r.resample && r.policy.kind == ResamplePolicy::Kind::local;
  const std::string resampling =
      r.resample ? "resample " + r.policy.to_string() + ": " + std::to_string(r.resamples) + " resamples"
                 : std::string("without resampling");
  std::snprintf(line, sizeof line, "%s: %dD, %s, h = %g, Delta = %gh%s, %s %s, %zu/%zu steps in %zu stage%s, %s\n",
                r.scene.c_str(), r.dimension, r.shape_source.c_str(), r.h, r.radius_factor,
                r.widen_support ? " (widened where the input is sparse)" : "", to_string(r.kind),
                to_string(r.variant), r.steps, r.steps_planned, r.stages, r.stages == 1 ? "" : "s",
                resampling.c_str());
  out << line;
  std::snprintf(line, sizeof line, "points: initial %zu, final %zu (min %zu, max %zu); spacing/h over %zu %sframes: min %.3f median %.3f max %.3f\n",
                r.points_initial, r.points_final, r.points_min, r.points_max, r.frames_measured,
                r.resample && !local ? "resampled " : "", r.spacing_h.min, r.spacing_h.median, r.spacing_h.max);
  out << line;
  if (r.spacing_sampled_frames > 0) {
    std::snprintf(line, sizeof line, "spacing measured on an even sample of %zu points in the %zu frames larger than that\n",
                  r.spacing_sample, r.spacing_sampled_frames);
    out << line;
  }
  std::snprintf(line, sizeof line, "spacing outside [%g h, %g h]: %zu below, %zu above, of %zu measured (%.3f %%)\n",
                kSpacingBandLow, kSpacingBandHigh, r.spacing_below, r.spacing_above, r.spacing_points,
                r.spacing_points > 0 ? 100.0 * static_cast<double>(r.spacing_below + r.spacing_above) /
                                           static_cast<double>(r.spacing_points)
                                     : 0.0);
  out << line;
  std::snprintf(line, sizeof line,
                "exact shape (%zu tracers): final points to it mean %.4f h, max %.4f h; it to the points mean %.4f h, max %.4f h\n",
                r.tracers, r.distance_to_exact_h.mean, r.distance_to_exact_h.max, r.exact_to_points_h.mean,
                r.exact_to_points_h.max);
  out << line;
  std::snprintf(line, sizeof line,
                "time: normals %.2f s, function %.2f s, resample %.2f s, deform %.2f s, hash %.2f s, total %.2f s "
                "(tracers %.2f s, measuring %.2f s, wall %.2f s)\n",
                r.timings.normals, r.timings.function, r.timings.resample, r.timings.deform, r.timings.hash,
                r.timings.total(), r.tracer_seconds, r.measure_seconds, r.wall_seconds);
  out << line;
  if (r.resample && r.policy.kind == ResamplePolicy::Kind::automatic) {
    std::snprintf(line, sizeof line, "sampling-quality checks (auto): %.3f s\n", r.quality_seconds);
    out << line;
  }
  if (r.final_holes > 0) {
    std::snprintf(line, sizeof line, "final surface: F undefined at %zu of %zu probes of the exact shape\n",
                  r.final_holes, r.probes);
    out << line;
  }
  out << "status: " << (r.broken ? "broken (" + r.status_reason + ")" : std::string("ok")) << "\n";
}

}  // namespace amls::app
