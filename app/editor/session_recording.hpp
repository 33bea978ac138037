#pragma once
// What a session did to its surface, kept so that Save Scene can write it as a
// scene (docs/scene-format.md, through core's write_scene) that `amls deform`
// replays to the session's final point set.
//
// `amls deform` runs R(P0), D1, R, D2, R, ..., DN, R: a resample of the shape's
// samples, then for each step the MLS deformation from the step's handles to
// the next ones followed by a resample - or, under a resample policy other
// than `always`, followed by a resample only where the policy asks for one.
// The session takes the same decisions on the same points (edit_session.hpp),
// so the recording keeps every deformation step the session actually took
// (its handles before and after) and checks what could make the replay differ:
// one grid, variant, MLS kind, alpha and policy throughout, resampling never
// switched off or on between steps. The replay passes the policy on the
// command line (`amls deform --resample auto`, replay_arguments()); a session
// that never resampled is replayed by `amls deform --no-resample`. Anything
// else (the variant toggled after a step, a grid change, resampling switched
// on and off) is recorded too, but the scene then says that its replay is not
// exact, and why. No GL.
#include <string>
#include <vector>

#include "app/editor/surface_settings.hpp"
#include "core/deform/deformation_history.hpp"
#include "core/run/scene.hpp"

namespace amls::editor {

template <int D>
struct RecordedStep {
  std::vector<Vec<D>> from;  // the handles before the step
  std::vector<Vec<D>> to;    // and after it
  std::vector<RegionHandle<D>> regions_from;  // the region handles before the step
  std::vector<RegionHandle<D>> regions_to;    // and after it
};

template <int D>
class SessionRecording {
 public:
  // The shape's points were sampled with `settings` (its spacing is h).
  SessionRecording(SceneShape<D> shape, const SurfaceSettings& settings);
  // A recording of the same shape from its start again, with these settings (reset).
  SessionRecording restarted(const SurfaceSettings& settings) const;

  // The surface was resampled (R) with these settings, or deformed (D) by the
  // MLS map taking handles `from` to `to` (and the regions `regions_from` to `regions_to`).
  void resampled(const SurfaceSettings& settings);
  void deformed(std::vector<Vec<D>> from, std::vector<Vec<D>> to, const SurfaceSettings& settings,
                std::vector<RegionHandle<D>> regions_from = {}, std::vector<RegionHandle<D>> regions_to = {});

  const SceneShape<D>& shape() const { return shape_; }
  // The grid spacing h the initial points were sampled at.
  double sampled_at() const { return sampled_at_; }
  // The settings a replay uses: those of the first resample and step (the
  // policy that step was taken under among them).
  const SurfaceSettings& settings() const { return settings_; }
  const std::vector<RecordedStep<D>>& steps() const { return steps_; }
  // Nothing was done to the initial points yet: neither a resample nor a step.
  bool untouched() const { return last_ == Op::none; }
  // The steps as the scene format's stages, one step per target. Consecutive
  // steps whose handles continue each other share a stage; a step whose
  // handles differ from where the last one left them (a handle was added,
  // removed or is new; a region was added, removed, pinned or let go) starts a stage.
  DeformationHistory<D> history() const;

  // Whether `amls deform` (with --no-resample if no_resample()) gives the
  // session's final point set exactly, and if not, why.
  bool exact() const { return inexact_reason().empty(); }
  std::string inexact_reason() const;
  bool no_resample() const { return mode_ == Mode::no_resample; }
  // What `amls deform` needs on its command line to replay the session:
  // "--no-resample", "--resample auto", "--resample every:K", or nothing.
  std::string replay_arguments() const;

 private:
  enum class Mode { undecided, resampling, no_resample };
  enum class Op { none, resample, deform };
  void spoil(const std::string& why);

  SceneShape<D> shape_;
  double sampled_at_;
  SurfaceSettings settings_;
  std::vector<RecordedStep<D>> steps_;
  Mode mode_ = Mode::undecided;
  Op last_ = Op::none;
  std::string spoiled_;  // the first reason the replay is not exact
};

// The recording as a scene for core's write_scene: `name` and a description
// that says how to replay it; a file shape's path relative to the folder of
// `scene_path`; a shape sampled at the grid's spacing gets the spacing it was
// sampled at if the session changed h before its first step. Throws
// std::runtime_error if there is no step to save (a scene needs a stage).
template <int D>
Scene<D> recorded_scene(const SessionRecording<D>& recording, const std::string& scene_path, const std::string& name);

extern template class SessionRecording<2>;
extern template class SessionRecording<3>;
extern template Scene<2> recorded_scene<2>(const SessionRecording<2>&, const std::string&, const std::string&);
extern template Scene<3> recorded_scene<3>(const SessionRecording<3>&, const std::string&, const std::string&);

}  // namespace amls::editor
