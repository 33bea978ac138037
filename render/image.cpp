#include "render/image.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>

#include "render/gl.hpp"
#include "render/gl_check.hpp"

// Debian's libstb-dev ships stb_image_write compiled in libstb.a (linked through
// pkg-config's stb), so this is the header only, without STB_IMAGE_WRITE_IMPLEMENTATION:
// a second copy would clash with the one Dear ImGui's libstb link brings into the editor.
#include <stb_image_write.h>

namespace amls {

Image read_framebuffer(const Viewport& viewport) {
  if (viewport.width <= 0 || viewport.height <= 0)
    throw std::invalid_argument("cannot read an empty framebuffer region (" + std::to_string(viewport.width) + "x" +
                                std::to_string(viewport.height) + ")");
  Image image{viewport.width, viewport.height, {}};
  const std::size_t row = 4 * static_cast<std::size_t>(viewport.width);
  std::vector<std::uint8_t> bottom_up(row * static_cast<std::size_t>(viewport.height));
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(viewport.x, viewport.y, viewport.width, viewport.height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
  check_gl("reading the framebuffer");
  image.rgba.resize(bottom_up.size());
  for (int y = 0; y < viewport.height; ++y) {
    const auto source = bottom_up.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y));
    std::copy(
        source, source + static_cast<std::ptrdiff_t>(row),
        image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(viewport.height - 1 - y)));
  }
  return image;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("cannot write an empty image (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ") to " + path.string());
  if (image.rgba.size() != 4 * static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("image data do not match its size " + std::to_string(image.width) + "x" +
                                std::to_string(image.height));
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  if (stbi_write_png(temporary.c_str(), image.width, image.height, 4, image.rgba.data(), 4 * image.width) == 0) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("could not write PNG " + path.string());
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error("could not write PNG " + path.string() + ": " + error.message());
  }
}

}  // namespace amls
