#include "core/run/scene_state.hpp"

#include <optional>
#include <stdexcept>

namespace amls {

template <int D>
std::vector<Vec<D>> handles_after(const DeformationHistory<D>& history, std::size_t steps) {
  const std::size_t total = history.total_steps();
  if (steps > total)
    throw std::out_of_range("the history has " + std::to_string(total) + " steps, not " + std::to_string(steps));
  if (history.stages.empty()) return {};
  if (steps < total) return history.step(steps).from;  // the handles before step K are those after K steps
  return history.step(total - 1).to;
}

template <int D>
SceneState<D> scene_state_after(const Scene<D>& scene, std::size_t steps, int threads, const SceneProgress& progress) {
  const std::size_t total = scene.history.total_steps();
  const std::string name = scene.path.empty() ? std::string("the scene") : scene.path;
  if (steps > total)
    throw std::invalid_argument(name + ": asked for the state after " + std::to_string(steps) +
                                " steps, but the scene has " + std::to_string(total));
  SceneRunOptions options;
  options.resample = true;
  options.threads = threads;
  options.tracers_per_point = 1.0;  // the run's measurements are not wanted here; keep the tracers cheap
  // max_steps = 0 would run the whole history; the state after 0 steps is frame 0 of a one-step run.
  options.max_steps = steps > 0 ? steps : 1;
  std::optional<PointSet<D>> frame;
  const SceneRunReport report = run_scene<D>(
      scene, options,
      [&](std::size_t k, const PointSet<D>& points) {
        if (k == steps) frame = points;
      },
      progress);
  if (!frame || frame->empty()) {
    const std::string why = report.broken ? report.status_reason : "no frame was made";
    throw std::runtime_error(name + ": the run did not reach a state after " + std::to_string(steps) +
                             " steps: " + why);
  }
  Vec<D> origin = report.grid_origin.template head<D>();
  SceneState<D> state{steps,
                      total,
                      std::move(*frame),
                      Grid<D>(origin, report.h),
                      scene.parameters(),
                      handles_after(scene.history, steps),
                      report.warnings};
  return state;
}

template std::vector<Vec<2>> handles_after<2>(const DeformationHistory<2>&, std::size_t);
template std::vector<Vec<3>> handles_after<3>(const DeformationHistory<3>&, std::size_t);
template SceneState<2> scene_state_after<2>(const Scene<2>&, std::size_t, int, const SceneProgress&);
template SceneState<3> scene_state_after<3>(const Scene<3>&, std::size_t, int, const SceneProgress&);

}  // namespace amls
