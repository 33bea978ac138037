#pragma once
// RGBA8 images: read back from the current framebuffer, written as PNG.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "render/render_options.hpp"

namespace amls {

// Rows top to bottom, 4 bytes (R, G, B, A) per pixel.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  // The pixel at column x, row y (from the top).
  const std::uint8_t* pixel(int x, int y) const { return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x); }
  bool operator==(const Image&) const = default;
};

// Reads `viewport` of the current framebuffer (after glFinish) and flips it top-down.
// Throws std::invalid_argument for an empty viewport.
Image read_framebuffer(const Viewport& viewport);

// Writes a PNG through a temporary file renamed into place, so a failed write never leaves
// a broken file. Throws std::invalid_argument for an empty image and std::runtime_error
// naming the path if it cannot be written.
void write_png(const std::filesystem::path& path, const Image& image);

}  // namespace amls
