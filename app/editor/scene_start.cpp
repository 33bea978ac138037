#include "app/editor/scene_start.hpp"

#include <filesystem>
#include <utility>

#include "core/io/point_set_io.hpp"
#include "core/run/scene_run.hpp"

namespace amls::editor {

template <int D>
InitialShape start_from_scene(const Scene<D>& scene, int threads) {
  // No tracers: the editor has no exact shape to measure against.
  SceneShapeSamples<D> samples = sample_scene_shape(scene, 0.0, threads);
  InitialShape start;
  if constexpr (D == 2) {
    start.points = to_3d(samples.points);
  } else {
    start.points = std::move(samples.points);
  }
  start.source = scene.shape;
  start.settings.spacing = scene.h();
  start.settings.radius_factor = scene.radius_factor;
  start.settings.widen_support = scene.widen_support;
  start.settings.variant = scene.variant;
  start.settings.kind = scene.kind;
  start.settings.alpha = scene.alpha;
  if (!scene.history.stages.empty()) {
    for (const Vec<D>& handle : scene.history.stages.front().start) {
      Vec<3> position = Vec<3>::Zero();
      position.template head<D>() = handle;
      start.handles.push_back(position);
    }
    start.regions = scene.history.stages.front().regions;
  }
  if (!scene.name.empty())
    start.name = scene.name;
  else if (!scene.path.empty())
    start.name = std::filesystem::path(scene.path).filename().string();
  else
    start.name = samples.source;
  start.warnings = std::move(samples.warnings);
  return start;
}

InitialShape load_scene_start(const std::string& path, int threads) {
  return std::visit([&](const auto& scene) { return start_from_scene(scene, threads); }, read_scene(path));
}

template InitialShape start_from_scene<2>(const Scene<2>&, int);
template InitialShape start_from_scene<3>(const Scene<3>&, int);

}  // namespace amls::editor
