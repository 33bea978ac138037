#pragma once
// `amls render`'s --view string, parsed into what render/picture.hpp takes
// (--size goes through parse_image_size, core/util/parameter_ranges.hpp).
#include <string>

#include "render/picture.hpp"

namespace amls {

// "az,el" or "az,el,dist" (--view). Throws std::invalid_argument saying what is wrong:
// not 2 or 3 numbers, a non-finite number, an elevation outside [-89.9, 89.9], a distance not above 0.
OrbitView parse_view(const std::string& text);

}  // namespace amls
