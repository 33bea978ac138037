#include "app/editor/surface_settings.hpp"

#include <cmath>
#include <stdexcept>

namespace amls::editor {

namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " must be a positive number, got " + std::to_string(value));
}

}  // namespace

void validate(const SurfaceSettings& settings) {
  require_positive(settings.spacing, "grid spacing h");
  require_positive(settings.radius_factor, "radius factor (Delta / h)");
  require_positive(settings.alpha, "MLS alpha");
  if (settings.policy.kind == ResamplePolicy::Kind::every && settings.policy.every < 1)
    throw std::invalid_argument("resample every K steps needs K >= 1, got " + std::to_string(settings.policy.every));
}

}  // namespace amls::editor
