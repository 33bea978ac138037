#include "app/deform_report.hpp"

#include <cstdio>
#include <ostream>
#include <string>

#include "core/surface/spacing_band.hpp"

namespace amls::app {

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
  if (r.start_first_pass_points > 0) {
    std::snprintf(line, sizeof line,
                  "start: the shape is sparser than h, so its first resample's %zu points were resampled once more "
                  "at h\n",
                  r.start_first_pass_points);
    out << line;
  }
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
