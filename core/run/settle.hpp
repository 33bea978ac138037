#pragma once
// The resample policy's part in the paper's loop (section 4), written once for
// `amls deform`, the editor and the flow tests: before step k the policy
// (core/resample/resample_policy.hpp) looks at the points P_k and decides
// whether S(P_k) is resampled. An editor session replays exactly as a scene
// because both decide here, from the same points, the same step index and the
// same h (the surface's grid).
#include <cstddef>
#include <functional>
#include <optional>

#include "core/resample/resample_policy.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/util/stopwatch.hpp"

namespace amls {

// Whether the policy resamples before step `step` (0-based) the points of
// `loop` (a DeformingSurface or RayTracingSurface), measured on the loop's own
// pool at its grid's h. Adds the seconds spent deciding (measuring the
// sampling under `auto`; not a phase of the loop) to `quality_seconds`.
template <typename Loop>
bool policy_resamples(const ResamplePolicy& policy, std::size_t step, Loop& loop, double& quality_seconds) {
  Stopwatch clock;
  const bool resample = policy.resample_now(step, loop.points(), loop.grid().spacing(), loop.pool());
  quality_seconds += clock.lap();
  return resample;
}

// Whether deciding before step `step` measures the points (and so is a phase
// of its own that a caller may want to announce).
bool policy_measures(const ResamplePolicy& policy, std::size_t step);

struct Settling {
  bool resampled = false;
  StepStats stats;  // of the resample, if there was one
  double quality_seconds = 0.0;
};

// Called before each phase of settle() that does work ("checking the sampling",
// "resampling"); returning false stops before it.
using SettlePhaseGate = std::function<bool(const char* phase)>;
inline constexpr const char* kCheckingPhase = "checking the sampling";
inline constexpr const char* kResamplingPhase = "resampling";

// The points before step `step`: the policy decides, and S(P) is resampled in
// place (DeformingSurface::resample_only; before step 0, resample_start), keeping the points that `held`
// regions hold (the region handles at their places before the step), if it
// said so. Empty if `gate` stopped it; the surface is then as before unless
// the resample had begun.
template <int D>
std::optional<Settling> settle(DeformingSurface<D>& surface, const ResamplePolicy& policy, std::size_t step,
                               const SettlePhaseGate& gate = {}, const HeldRegions<D>& held = {});

extern template std::optional<Settling> settle<2>(DeformingSurface<2>&, const ResamplePolicy&, std::size_t,
                                                  const SettlePhaseGate&, const HeldRegions<2>&);
extern template std::optional<Settling> settle<3>(DeformingSurface<3>&, const ResamplePolicy&, std::size_t,
                                                  const SettlePhaseGate&, const HeldRegions<3>&);

}  // namespace amls
