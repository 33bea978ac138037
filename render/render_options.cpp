#include "render/render_options.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace amls {

ColorMode color_mode_from_string(const char* name) {
  const std::string s = name ? name : "";
  if (s == "uniform") return ColorMode::uniform;
  if (s == "normal") return ColorMode::normal;
  if (s == "scalar" || s == "quality") return ColorMode::scalar;
  throw std::invalid_argument("unknown colour mode '" + s + "' (expected uniform, normal or quality)");
}

const char* to_string(ColorMode mode) {
  switch (mode) {
    case ColorMode::uniform:
      return "uniform";
    case ColorMode::normal:
      return "normal";
    case ColorMode::scalar:
      return "scalar";
  }
  return "uniform";
}

void validate(const RenderOptions& o) {
  const std::pair<const char*, float> sizes[] = {
      {"splat_scale", o.splat_scale},       {"point_size_px", o.point_size_px}, {"normal_length", o.normal_length},
      {"handle_size_px", o.handle_size_px}, {"line_width_px", o.line_width_px}, {"grid_spacing", o.grid_spacing}};
  for (const auto& [name, value] : sizes)
    if (!(value >= 0.0f) || !std::isfinite(value))
      throw std::invalid_argument(std::string("render option ") + name + " must be a finite number >= 0, got " +
                                  std::to_string(value));
}

}  // namespace amls
