#pragma once
// `amls render`'s option strings: --view and --size, parsed into what
// render/picture.hpp takes.
#include <string>

#include "render/picture.hpp"

namespace amls {

// "az,el" or "az,el,dist" (--view). Throws std::invalid_argument saying what is wrong:
// not 2 or 3 numbers, a non-finite number, an elevation outside [-89.9, 89.9], a distance not above 0.
OrbitView parse_view(const std::string& text);

// "WxH", e.g. "480x360": each from 1 to 16384. Throws std::invalid_argument otherwise.
ImageSize parse_image_size(const std::string& text);

}  // namespace amls
