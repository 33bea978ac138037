#pragma once
// Seconds per named phase of a deformation loop, in the order the loop's table
// lists them (the rows of the paper's Table 1). Loops with different phases
// (the grid walk's, the ray-tracing baseline's) report through this one type.
#include <string>
#include <vector>

namespace amls {

struct PhaseTime {
  std::string phase;
  double seconds = 0.0;
};

using PhaseTimes = std::vector<PhaseTime>;

inline double total_seconds(const PhaseTimes& phases) {
  double total = 0.0;
  for (const PhaseTime& p : phases) total += p.seconds;
  return total;
}

// The seconds of `phase`, or 0 if the loop has no such phase.
inline double seconds_of(const PhaseTimes& phases, const std::string& phase) {
  for (const PhaseTime& p : phases)
    if (p.phase == phase) return p.seconds;
  return 0.0;
}

}  // namespace amls
