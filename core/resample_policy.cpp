#include "core/resample_policy.hpp"

#include <stdexcept>

#include "core/metrics.hpp"

namespace amls {


ResamplePolicy ResamplePolicy::parse(const std::string& text) {
  ResamplePolicy p;
  if (text == "always") return p;
  if (text == "auto") {
    p.kind = Kind::automatic;
    return p;
  }
  const std::string prefix = "every:";
  if (text.rfind(prefix, 0) == 0) {
    std::size_t used = 0;
    int k = 0;
    try {
      k = std::stoi(text.substr(prefix.size()), &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == text.size() - prefix.size() && k >= 1) {
      p.kind = Kind::every;
      p.every = k;
      return p;
    }
  }
  throw std::invalid_argument("--resample must be always, auto or every:K with K >= 1, got '" + text + "'");
}

std::string ResamplePolicy::to_string() const {
  switch (kind) {
    case Kind::always: return "always";
    case Kind::automatic: return "auto";
    case Kind::every: return "every:" + std::to_string(every);
  }
  return "always";
}

template <int D>
bool ResamplePolicy::resample_now(std::size_t step, const PointSet<D>& points, double h) const {
  switch (kind) {
    case Kind::always: return true;
    case Kind::every: return step % static_cast<std::size_t>(every) == 0;
    case Kind::automatic: {
      if (step == 0 || points.size() < 2) return true;
      const SpacingStats s = spacing_stats(points, h);
      return s.min < min_spacing || s.max > max_spacing;
    }
  }
  return true;
}

template bool ResamplePolicy::resample_now<2>(std::size_t, const PointSet<2>&, double) const;
template bool ResamplePolicy::resample_now<3>(std::size_t, const PointSet<3>&, double) const;

}  // namespace amls
