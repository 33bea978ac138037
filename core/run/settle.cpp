#include "core/run/settle.hpp"

namespace amls {

bool policy_measures(const ResamplePolicy& policy, std::size_t step) {
  return policy.kind == ResamplePolicy::Kind::automatic && step > 0;
}

template <int D>
std::optional<Settling> settle(DeformingSurface<D>& surface, const ResamplePolicy& policy, std::size_t step,
                               const SettlePhaseGate& gate, const HeldRegions<D>& held) {
  Settling out;
  if (gate && policy_measures(policy, step) && !gate(kCheckingPhase)) return std::nullopt;
  out.resampled = policy_resamples(policy, step, surface, out.quality_seconds);
  if (!out.resampled) return out;
  if (gate && !gate(kResamplingPhase)) return std::nullopt;
  // Step 0 resamples the shape's own samples: the start's resample, which
  // fills a sparse scan's first holes at once (DeformingSurface::resample_start).
  out.stats = step == 0 && held.empty() ? surface.resample_start() : surface.resample_only(held);
  return out;
}

template std::optional<Settling> settle<2>(DeformingSurface<2>&, const ResamplePolicy&, std::size_t,
                                           const SettlePhaseGate&, const HeldRegions<2>&);
template std::optional<Settling> settle<3>(DeformingSurface<3>&, const ResamplePolicy&, std::size_t,
                                           const SettlePhaseGate&, const HeldRegions<3>&);

}  // namespace amls
