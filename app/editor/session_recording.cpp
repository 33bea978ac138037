#include "app/editor/session_recording.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace amls::editor {

namespace {

using nlohmann::ordered_json;

template <int D>
ordered_json point_json(const Vec<D>& p) {
  ordered_json a = ordered_json::array();
  for (int i = 0; i < D; ++i) a.push_back(p[i]);
  return a;
}

template <int D>
ordered_json points_json(const std::vector<Vec<D>>& points) {
  ordered_json a = ordered_json::array();
  for (const Vec<D>& p : points) a.push_back(point_json<D>(p));
  return a;
}

// A file shape's path as the scene at `scene_path` must name it: relative to the scene's folder.
std::string path_from_scene(const std::string& file, const std::string& scene_path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path target = fs::absolute(file, error);
  const fs::path folder = fs::absolute(fs::path(scene_path), error).parent_path();
  const fs::path relative = target.lexically_relative(folder);
  return relative.empty() ? target.string() : relative.string();
}

template <int D>
ordered_json shape_json(const ShapeSource& shape, const std::string& scene_path) {
  if (shape.type == ShapeSource::Type::file)
    return ordered_json{{"type", "file"}, {"path", path_from_scene(shape.path, scene_path)}};
  return ordered_json{{"type", shape.type == ShapeSource::Type::circle ? "circle" : "sphere"},
                      {"center", point_json<D>(shape.center.template head<D>())},
                      {"radius", shape.radius},
                      {"points", shape.points}};
}

}  // namespace

template <int D>
SessionRecording<D>::SessionRecording(ShapeSource shape, const SurfaceSettings& settings)
    : shape_(std::move(shape)), settings_(settings) {}

template <int D>
void SessionRecording<D>::spoil(const std::string& why) {
  if (spoiled_.empty()) spoiled_ = why;
}

template <int D>
void SessionRecording<D>::resampled(const SurfaceSettings& settings) {
  if (last_ == Op::resample)
    spoil("the surface was resampled twice in a row (the variant or the grid changed without a step between)");
  if (mode_ == Mode::no_resample) spoil("resampling was switched on after steps without it");
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
void SessionRecording<D>::deformed(std::vector<Vec<D>> from, std::vector<Vec<D>> to, const SurfaceSettings& settings) {
  if (steps_.empty()) {
    settings_.kind = settings.kind;
    settings_.alpha = settings.alpha;
  } else if (settings.kind != settings_.kind || settings.alpha != settings_.alpha) {
    spoil("the MLS kind or alpha changed after the first step");
  }
  if (mode_ == Mode::undecided) mode_ = Mode::no_resample;
  if (mode_ == Mode::resampling && last_ != Op::resample)
    spoil("a step was taken without resampling between resampled ones");
  steps_.push_back(RecordedStep<D>{std::move(from), std::move(to)});
  last_ = Op::deform;
}

template <int D>
std::vector<RecordedStage<D>> SessionRecording<D>::stages() const {
  std::vector<RecordedStage<D>> out;
  for (const RecordedStep<D>& step : steps_) {
    const bool continues = !out.empty() && out.back().targets.back() == step.from;
    if (!continues) out.push_back(RecordedStage<D>{step.from, {}});
    out.back().targets.push_back(step.to);
  }
  return out;
}

template <int D>
std::string SessionRecording<D>::inexact_reason() const {
  if (!spoiled_.empty()) return spoiled_;
  if (mode_ == Mode::resampling && last_ == Op::deform) return "the last step was not followed by a resample";
  return {};
}

template <int D>
ordered_json scene_json(const SessionRecording<D>& recording, const std::string& scene_path, const std::string& name) {
  if (recording.steps().empty())
    throw std::runtime_error("nothing to save yet: the session has taken no deformation step (drag a handle first)");
  const std::vector<RecordedStage<D>> stages = recording.stages();
  std::string description = "Recorded by amls-editor: " + std::to_string(recording.steps().size()) + " steps in " +
                            std::to_string(stages.size()) + " stages. ";
  if (!recording.exact())
    description += "The replay is not exact: " + recording.inexact_reason() + ".";
  else if (recording.no_resample())
    description += "`amls deform --no-resample` replays it to the session's final point set.";
  else
    description += "`amls deform` replays it to the session's final point set.";

  const SurfaceSettings& s = recording.settings();
  ordered_json scene;
  scene["dimension"] = D;
  scene["name"] = name;
  scene["description"] = description;
  scene["shape"] = shape_json<D>(recording.shape(), scene_path);
  scene["grid"] = ordered_json{{"spacing", s.spacing}};
  scene["radius_factor"] = s.radius_factor;
  scene["variant"] = to_string(s.variant);
  scene["deformation"] = ordered_json{{"kind", to_string(s.kind)}, {"alpha", s.alpha}};
  ordered_json stage_array = ordered_json::array();
  for (const RecordedStage<D>& stage : stages) {
    ordered_json targets = ordered_json::array();
    for (const std::vector<Vec<D>>& target : stage.targets)
      targets.push_back(ordered_json{{"steps", 1}, {"handles", points_json<D>(target)}});
    stage_array.push_back(ordered_json{{"handles", points_json<D>(stage.start)}, {"targets", targets}});
  }
  scene["stages"] = stage_array;
  return scene;
}

template class SessionRecording<2>;
template class SessionRecording<3>;
template ordered_json scene_json<2>(const SessionRecording<2>&, const std::string&, const std::string&);
template ordered_json scene_json<3>(const SessionRecording<3>&, const std::string&, const std::string&);

}  // namespace amls::editor
