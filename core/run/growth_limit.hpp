#pragma once
// A resampling run is broken when its point set grows past kMaxGrowth times
// its start: the surface has torn into clusters or spurious sheets that every
// resample multiplies, and the run would only slow down and fill memory.
#include <cstddef>
#include <string>

namespace amls {

inline constexpr int kMaxGrowth = 20;

inline bool grew_past_limit(std::size_t points, std::size_t initial) {
  return static_cast<double>(points) > static_cast<double>(kMaxGrowth) * static_cast<double>(initial);
}

// Why the run broke at `step`, for its report.
inline std::string growth_breakdown(std::size_t step) {
  return "the point set grew past " + std::to_string(kMaxGrowth) + " times its start at step " + std::to_string(step);
}

}  // namespace amls
