#pragma once
// Helpers for the editor's GL-free tests: `amls deform` on a recorded session
// (and TempDir, from temp_dir.hpp).
#include <string>
#include <variant>

#include "app/editor/session_recording.hpp"
#include "core/run/scene.hpp"
#include "core/run/scene_run.hpp"
#include "temp_dir.hpp"

namespace amls::test {

// What `amls deform` (with the recording's replay_arguments(): --no-resample,
// or the session's resample policy) makes of
// the session saved as a scene: written by core's write_scene, read back by
// read_scene and run by run_scene. Returns its final point set.
template <int D>
PointSet<D> replay_with_amls_deform(const editor::SessionRecording<D>& recording) {
  TempDir dir;
  const std::string path = dir.file("session.json");
  write_scene(path, editor::recorded_scene(recording, path, "session"));
  SceneRunOptions options;
  options.resample = !recording.no_resample();
  options.policy = recording.settings().policy;
  options.tracers_per_point = 1.0;  // the run's measurements against the exact shape are not compared here
  PointSet<D> final_points;
  const FrameSink<D> keep_last = [&](std::size_t, const PointSet<D>& points) { final_points = points; };
  run_scene(std::get<Scene<D>>(read_scene(path)), options, keep_last);
  return final_points;
}

}  // namespace amls::test
