#include "core/run/resampling_report.hpp"

#include <stdexcept>

namespace amls {

template <int D>
nlohmann::json resampling_report_json(const ResampledPointSet<D>& result, const PointSetResampling& options,
                                      const ResamplingRun& run) {
  const Coverage& c = result.coverage;
  const RimReport& rim = result.rim;
  nlohmann::json j;
  j["input"] = run.input;
  j["output"] = run.output;
  j["dimension"] = D;
  j["variant"] = to_string(options.variant);
  j["h"] = result.grid.spacing();
  j["radius_factor"] = options.radius_factor;
  j["support"] = {{"widened", options.widen_support},
                  {"widened_points", result.widening.widened_points},
                  {"widest", result.widening.widest}};
  j["file_points"] = run.file_points;  // a mesh's vertices
  j["points_in"] = run.points_in;      // a mesh's samples
  const std::size_t first_pass = result.stats.first_pass_points;
  j["passes"] = first_pass > 0 ? 2 : 1;
  j["first_pass_points"] = first_pass > 0 ? first_pass : result.points.size();
  j["points_out"] = result.points.size();
  j["spacing_h"] = {{"min", result.spacing_h.min}, {"median", result.spacing_h.median}, {"max", result.spacing_h.max}};
  j["coverage"] = {{"reach", kCoverageReach},
                   {"input_covered", c.input_fraction()},
                   {"output_on_input", c.output_fraction()},
                   {"input_uncovered_points", c.input_points - c.input_covered},
                   {"output_off_points", c.output_points - c.output_on_input},
                   {"gap_reach", kGapReach},
                   {"output_in_gaps", c.gap_fraction()},
                   {"output_gap_points", c.output_in_gaps},
                   {"clear_loss", c.clear_loss()}};
  j["rim"] = {{"samples_in", rim.samples_in}, {"samples_out", rim.samples_out}, {"advance_h", rim.advance_h}};
  j["seconds"] = run.seconds;
  j["peak_memory_mib"] = run.peak_memory_mib;
  return j;
}

template <int D>
void require_resampled_points(const ResampledPointSet<D>& result, const PointSetResampling& options) {
  if (!result.points.empty()) return;
  throw std::runtime_error(
      "resampling produced no points: the surface has no crossing with the grid near the "
      "points (is the input too sparse for h = " +
      std::to_string(result.grid.spacing()) + " and --radius-factor " + std::to_string(options.radius_factor) + "?)");
}

template nlohmann::json resampling_report_json<2>(const ResampledPointSet<2>&, const PointSetResampling&,
                                                  const ResamplingRun&);
template nlohmann::json resampling_report_json<3>(const ResampledPointSet<3>&, const PointSetResampling&,
                                                  const ResamplingRun&);
template void require_resampled_points<2>(const ResampledPointSet<2>&, const PointSetResampling&);
template void require_resampled_points<3>(const ResampledPointSet<3>&, const PointSetResampling&);

}  // namespace amls
