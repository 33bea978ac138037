#pragma once
// Helpers for the editor's GL-free tests: the replay of a recorded session
// the way `amls deform` runs a scene (and TempDir, from temp_dir.hpp).
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "app/editor/session_recording.hpp"
#include "temp_dir.hpp"
#include "core/deforming_surface.hpp"
#include "core/mls_deformation.hpp"
#include "core/point_set_resampling.hpp"

namespace amls::test {

// The loop of `amls deform` (core/scene_run.cpp on the scenes branch): R(P0),
// then for each step D and R (without resampling: only the D's), on the grid
// anchored by the initial points.
template <int D>
PointSet<D> replay_like_amls_deform(const PointSet<D>& initial, const editor::SessionRecording<D>& recording) {
  const editor::SurfaceSettings& s = recording.settings();
  PointSetResampling grid_options;
  grid_options.spacing = s.spacing;
  grid_options.radius_factor = s.radius_factor;
  DeformingSurface<D> surface(resampling_grid(initial, grid_options), AmlsParameters{s.radius_factor}, s.variant, 1);
  surface.set_points(initial);
  const bool resample = !recording.no_resample();
  for (const editor::RecordedStep<D>& step : recording.steps()) {
    if (resample) surface.resample_only();
    surface.step(MlsDeformation<D>(step.from, step.to, s.kind, s.alpha), 0.0, 1.0, false);
  }
  if (resample) surface.resample_only();
  return surface.points();
}

}  // namespace amls::test
