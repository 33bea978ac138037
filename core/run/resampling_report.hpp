#pragma once
// What one resampling of a point set (core/run/point_set_resampling.hpp)
// reports: `amls resample --json`'s keys, made here so that the command line
// and the Python module's resample() give the same report, and the check
// that a resampling produced points, with the command line's message.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "core/run/point_set_resampling.hpp"

namespace amls {

// The run's settings and measures that the result does not hold.
struct ResamplingRun {
  std::string input;   // the file read ("" for points given in memory)
  std::string output;  // the file written ("" for none)
  std::size_t file_points = 0;  // the points the file holds (a mesh: its vertices)
  std::size_t points_in = 0;    // the points resampled (a mesh: its samples)
  double seconds = 0.0;
  double peak_memory_mib = 0.0;
};

template <int D>
nlohmann::json resampling_report_json(const ResampledPointSet<D>& result, const PointSetResampling& options,
                                      const ResamplingRun& run);

// Throws std::runtime_error when the resampling produced no points, naming h
// and the radius factor.
template <int D>
void require_resampled_points(const ResampledPointSet<D>& result, const PointSetResampling& options);

extern template nlohmann::json resampling_report_json<2>(const ResampledPointSet<2>&, const PointSetResampling&,
                                                         const ResamplingRun&);
extern template nlohmann::json resampling_report_json<3>(const ResampledPointSet<3>&, const PointSetResampling&,
                                                         const ResamplingRun&);
extern template void require_resampled_points<2>(const ResampledPointSet<2>&, const PointSetResampling&);
extern template void require_resampled_points<3>(const ResampledPointSet<3>&, const PointSetResampling&);

}  // namespace amls
