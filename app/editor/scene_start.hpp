#pragma once
// A session's start from a scene (docs/scene-format.md): read and checked by
// core's read_scene, the initial shape sampled by core's sample_scene_shape -
// the points `amls deform` starts from, for every shape type - with the
// scene's grid, AMLS and MLS parameters and its first stage's handles and
// region handles (their members, reach, motions and pins as read). The
// stages are not played: the editor's user drags the handles. No GL.
#include <string>

#include "app/editor/surface_settings.hpp"
#include "core/run/scene.hpp"

namespace amls::editor {

// The name is the scene's, else its file's, else what the samples are
// ("circle of 250 points"). Throws std::runtime_error naming the scene file
// for a shape file that cannot be read or has the wrong dimension.
template <int D>
InitialShape start_from_scene(const Scene<D>& scene, int threads);

// Throws std::runtime_error with core's message, which names the file and the
// key (`s.json: shape.radius: ...`), for a scene it refuses.
InitialShape load_scene_start(const std::string& path, int threads);

extern template InitialShape start_from_scene<2>(const Scene<2>&, int);
extern template InitialShape start_from_scene<3>(const Scene<3>&, int);

}  // namespace amls::editor
