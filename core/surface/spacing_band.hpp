#pragma once
// The band, in units of h, that the grid resampler keeps nearest-neighbour
// spacing within: closer points are crowding, farther ones a thinning surface
// about to tear. `amls deform` counts the points outside it, and `amls render
// --color quality` spans its colour ramp over it.
#include <cstdio>
#include <string>

namespace amls {

inline constexpr double kSpacingBandLow = 0.3;
inline constexpr double kSpacingBandHigh = 1.5;

// A bound of the band as text ("0.3"), for messages and report keys.
inline std::string spacing_band_text(double bound) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", bound);
  return text;
}

}  // namespace amls
