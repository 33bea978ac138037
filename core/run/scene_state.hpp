#pragma once
// A scene's state after K steps of its deformation history, for pictures and
// inspection: exactly the point set that `amls deform` writes as frame K (the
// surface resampled after K steps, R_K; see core/run/scene_run.hpp), with the grid
// and parameters that define its AMLS surface and the handles at that moment.
#include <cstddef>
#include <string>
#include <vector>

#include "core/surface/amls_surface.hpp"
#include "core/run/scene.hpp"
#include "core/run/scene_run.hpp"

namespace amls {

template <int D>
struct SceneState {
  std::size_t step = 0;         // K
  std::size_t total_steps = 0;  // of the scene's whole history
  PointSet<D> points;           // R_K
  Grid<D> grid;                 // the run's grid (spacing h)
  AmlsParameters parameters;    // as the run used them (the scene's)
  std::vector<Vec<D>> handles;  // the handle positions after K steps (none without stages)
  std::vector<std::string> warnings;
};

// The handles after `steps` steps of `history` (0: the first stage's start); empty
// for a history without stages. Throws std::out_of_range past total_steps().
template <int D>
std::vector<Vec<D>> handles_after(const DeformationHistory<D>& history, std::size_t steps);

// Runs the scene's deformation loop for `steps` steps (run_scene with resampling)
// and returns its state then. Throws std::invalid_argument naming the scene if
// `steps` exceeds its history, std::runtime_error if the run breaks (its point
// set vanishes or explodes) before step `steps`, plus what run_scene throws.
template <int D>
SceneState<D> scene_state_after(const Scene<D>& scene, std::size_t steps, int threads = 1,
                                const SceneProgress& progress = {});

extern template std::vector<Vec<2>> handles_after<2>(const DeformationHistory<2>&, std::size_t);
extern template std::vector<Vec<3>> handles_after<3>(const DeformationHistory<3>&, std::size_t);
extern template SceneState<2> scene_state_after<2>(const Scene<2>&, std::size_t, int, const SceneProgress&);
extern template SceneState<3> scene_state_after<3>(const Scene<3>&, std::size_t, int, const SceneProgress&);

}  // namespace amls
