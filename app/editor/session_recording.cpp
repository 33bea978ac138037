#include "app/editor/session_recording.hpp"

#include <filesystem>
#include <stdexcept>

namespace amls::editor {

namespace {

// A file shape's path as the scene at `scene_path` must name it: relative to the scene's folder.
std::string path_from_scene(const std::string& file, const std::string& scene_path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path target = fs::absolute(file, error);
  const fs::path folder = fs::absolute(fs::path(scene_path), error).parent_path();
  const fs::path relative = target.lexically_relative(folder);
  return relative.empty() ? target.string() : relative.string();
}

}  // namespace

template <int D>
SessionRecording<D>::SessionRecording(SceneShape<D> shape, const SurfaceSettings& settings)
    : shape_(std::move(shape)), sampled_at_(settings.spacing), settings_(settings) {}

template <int D>
SessionRecording<D> SessionRecording<D>::restarted(const SurfaceSettings& settings) const {
  SessionRecording<D> fresh(shape_, settings);
  fresh.sampled_at_ = sampled_at_;
  return fresh;
}

template <int D>
void SessionRecording<D>::spoil(const std::string& why) {
  if (spoiled_.empty()) spoiled_ = why;
}

template <int D>
void SessionRecording<D>::resampled(const SurfaceSettings& settings) {
  if (last_ == Op::resample)
    spoil("the surface was resampled twice in a row (the variant or the grid changed without a step between)");
  if (mode_ == Mode::no_resample) spoil("resampling was switched on after steps without it");
  if (!steps_.empty() && settings.resample && settings.policy.kind == ResamplePolicy::Kind::local)
    spoil("under local, the whole surface was resampled after the first step (an undo, or resampling switched off "
          "and on)");
  if (steps_.empty()) {
    settings_.spacing = settings.spacing;
    settings_.radius_factor = settings.radius_factor;
    settings_.variant = settings.variant;
  } else if (!settings.same_grid(settings_) || settings.variant != settings_.variant) {
    spoil("the grid or the variant changed after the first step");
  }
  mode_ = Mode::resampling;
  last_ = Op::resample;
}

template <int D>
void SessionRecording<D>::deformed(std::vector<Vec<D>> from, std::vector<Vec<D>> to, const SurfaceSettings& settings,
                                   std::vector<RegionHandle<D>> regions_from, std::vector<RegionHandle<D>> regions_to) {
  if (steps_.empty()) {
    settings_.kind = settings.kind;
    settings_.alpha = settings.alpha;
    settings_.policy = settings.policy;
  } else if (settings.kind != settings_.kind || settings.alpha != settings_.alpha) {
    spoil("the MLS kind or alpha changed after the first step");
  }
  if (mode_ == Mode::undecided) mode_ = Mode::no_resample;
  // A step without a resample after it is the policy's choice, which the
  // replay takes again, as long as it is the same policy.
  if (mode_ == Mode::resampling && !settings.resample)
    spoil("resampling was switched off after resampled steps");
  if (mode_ == Mode::resampling && settings.resample && !(settings.policy == settings_.policy))
    spoil("the resample policy changed after the first step");
  steps_.push_back(
      RecordedStep<D>{std::move(from), std::move(to), std::move(regions_from), std::move(regions_to)});
  last_ = Op::deform;
}

template <int D>
DeformationHistory<D> SessionRecording<D>::history() const {
  DeformationHistory<D> out;
  const std::vector<RegionHandle<D>>* last_regions = nullptr;  // where the last step left the regions
  for (const RecordedStep<D>& step : steps_) {
    // Pinned or not is the stage's: a region pinned or let go starts one, as a region added or removed does.
    const bool continues = !out.stages.empty() && out.stages.back().targets.back().handles == step.from &&
                           *last_regions == step.regions_from;
    if (!continues) out.begin_stage(step.from, step.regions_from);
    std::vector<RegionMotion<D>> motions;
    for (const RegionHandle<D>& region : step.regions_to) motions.push_back(region.motion);
    out.add_target(step.to, 1, std::move(motions));
    last_regions = &step.regions_to;
  }
  return out;
}

template <int D>
std::string SessionRecording<D>::inexact_reason() const {
  return spoiled_;
}

template <int D>
std::string SessionRecording<D>::replay_arguments() const {
  if (mode_ == Mode::no_resample) return "--no-resample";
  if (mode_ == Mode::resampling && settings_.policy.kind != ResamplePolicy::Kind::always)
    return "--resample " + settings_.policy.to_string();
  return {};
}

template <int D>
Scene<D> recorded_scene(const SessionRecording<D>& recording, const std::string& scene_path, const std::string& name) {
  if (recording.steps().empty())
    throw std::runtime_error("nothing to save yet: the session has taken no deformation step (drag a handle first)");
  Scene<D> scene;
  scene.path = scene_path;
  scene.name = name;
  scene.history = recording.history();
  scene.description = "Recorded by amls-editor: " + std::to_string(recording.steps().size()) + " steps in " +
                      std::to_string(scene.history.stages.size()) + " stages. ";
  const std::string arguments = recording.replay_arguments();
  if (!recording.exact())
    scene.description += "The replay is not exact: " + recording.inexact_reason() + ".";
  else
    scene.description += "`amls deform" + (arguments.empty() ? "" : " " + arguments) +
                         "` replays it to the session's final point set.";

  const SurfaceSettings& s = recording.settings();
  scene.shape = recording.shape();
  if (scene.shape.type == ShapeType::file) scene.shape.file = path_from_scene(scene.shape.resolved_file, scene_path);
  // A shape without its own spacing or point count is sampled at h: at the h
  // it was loaded with, which the saved grid no longer says if it changed.
  if (scene.shape.points == 0 && scene.shape.spacing == 0.0 && s.spacing != recording.sampled_at())
    scene.shape.spacing = recording.sampled_at();
  scene.grid_spacing = s.spacing;
  scene.radius_factor = s.radius_factor;
  scene.widen_support = s.widen_support;
  scene.variant = s.variant;
  scene.kind = s.kind;
  scene.alpha = s.alpha;
  return scene;
}

template class SessionRecording<2>;
template class SessionRecording<3>;
template Scene<2> recorded_scene<2>(const SessionRecording<2>&, const std::string&, const std::string&);
template Scene<3> recorded_scene<3>(const SessionRecording<3>&, const std::string&, const std::string&);

}  // namespace amls::editor
