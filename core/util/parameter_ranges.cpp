#include "core/util/parameter_ranges.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

namespace amls {

std::string format_number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string out_of_range_text(double value, const ParameterRange& range) {
  std::string text = "must be within [" + format_number(range.min) + ", " + format_number(range.max) + "]";
  if (range.meaning && *range.meaning) text += std::string(" (") + range.meaning + ")";
  return text + ", got " + format_number(value);
}

void check_range(const std::string& key, double value, const ParameterRange& range) {
  if (!range.contains(value)) throw std::invalid_argument(key + ": " + out_of_range_text(value, range));
}

ImageSize parse_image_size(const std::string& text, const std::string& key, int min_side) {
  const int max_side = static_cast<int>(ranges::kImageSide.max);
  const std::string expected = "expected WIDTHxHEIGHT with each side a whole number within [" +
                               std::to_string(min_side) + ", " + std::to_string(max_side) + "] pixels, e.g. 800x600";
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) throw std::invalid_argument(key + ": " + expected + ", got '" + text + "'");
  auto side = [&](std::size_t begin, std::size_t end) {
    int value = 0;
    const char* first = text.data() + begin;
    const char* last = text.data() + end;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (first == last || ec != std::errc() || ptr != last || value < min_side || value > max_side)
      throw std::invalid_argument(key + ": " + expected + ", got '" + text + "'");
    return value;
  };
  return {side(0, x), side(x + 1, text.size())};
}

}  // namespace amls
