#pragma once
// Scene files the reader must refuse: the message one is refused with, and a
// good scene's text with one edit.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "core/run/scene.hpp"
#include "tests/temp_dir.hpp"

namespace amls::test {

// The message `text`, written to a scene file in `dir`, is refused with; "(accepted)" if it is read.
inline std::string scene_error_of(const std::string& text, const TempDir& dir) {
  const std::string path = dir.file("scene.json");
  write_text(path, text);
  try {
    read_scene(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(accepted)";
}

// `text` with its first `from` replaced by `to` (which must be there).
inline std::string edited_text(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace amls::test
