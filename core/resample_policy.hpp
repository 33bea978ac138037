#pragma once
// When the deformation loop resamples. The paper resamples after every
// deformation step and names quality-triggered resampling as an improvement;
// `auto` does that: it resamples only when the deformed points' nearest-
// neighbour spacing leaves a band (units of h): crowding below min_spacing, or
// stretching above max_spacing. Nearest-neighbour spacing sees uniform
// stretching and crowding, not a local hole (the points at a hole's rim keep
// their other neighbours): on the vortex, `auto` leaves a tail at the
// filament's tip (README).
#include <string>

#include "core/point_set.hpp"

namespace amls {

struct ResamplePolicy {
  enum class Kind { always, automatic, every };
  Kind kind = Kind::always;
  int every = 1;  // Kind::every: resample on steps 0, K, 2K, ...
  // Kind::automatic: the band (units of h). Right after a resample the
  // nearest-neighbour spacing lies in about [0.5, 1.6].
  double min_spacing = 0.25;
  double max_spacing = 2.0;

  // "always", "auto" or "every:K"; throws std::invalid_argument naming the accepted forms.
  static ResamplePolicy parse(const std::string& text);
  std::string to_string() const;

  // Whether step `step` (0-based) resamples, given the points as they are now.
  template <int D>
  bool resample_now(std::size_t step, const PointSet<D>& points, double h) const;
};

}  // namespace amls
