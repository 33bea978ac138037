#pragma once
// The start of a scene (docs/scene-format.md on the scenes branch): its
// dimension, initial shape (circle, sphere or point-set file), grid, AMLS and
// MLS parameters, and the first stage's handles. The stages themselves are not
// played: the editor's user drags the handles. This reads the subset of the
// format the editor needs until core/scene.hpp (scenes branch) replaces it.
#include <string>

#include "app/editor/surface_settings.hpp"

namespace amls::editor {

// Throws std::runtime_error naming the file and the key for a file that cannot
// be read, invalid JSON, a missing or bad value, or a shape type the editor
// cannot build yet (ellipse, torus, rounded_box).
InitialShape load_scene_start(const std::string& path);

}  // namespace amls::editor
