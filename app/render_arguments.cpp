#include "app/render_arguments.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace amls {

namespace {

float parse_float(const std::string& text, const std::string& what) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw std::invalid_argument(what + ": '" + text + "' is not a number");
  if (!std::isfinite(value)) throw std::invalid_argument(what + ": " + text + " is not finite");
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if (end == std::string::npos) return parts;
    begin = end + 1;
  }
}

}  // namespace

OrbitView parse_view(const std::string& text) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() != 2 && parts.size() != 3)
    throw std::invalid_argument(
        "--view must be 'azimuth,elevation' or 'azimuth,elevation,distance' (degrees, "
        "degrees, world units), got '" +
        text + "'");
  OrbitView view;
  view.azimuth_deg = parse_float(parts[0], "--view azimuth");
  view.elevation_deg = parse_float(parts[1], "--view elevation");
  if (std::abs(view.elevation_deg) > 89.9f)
    throw std::invalid_argument("--view elevation must be within [-89.9, 89.9] degrees, got " + parts[1]);
  if (parts.size() == 3) {
    view.distance = parse_float(parts[2], "--view distance");
    if (!(*view.distance > 0.0f)) throw std::invalid_argument("--view distance must be above 0, got " + parts[2]);
  }
  return view;
}

}  // namespace amls
