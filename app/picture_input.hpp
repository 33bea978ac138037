#pragma once
// What `amls render` draws, read from its input file into a Picture
// (render/picture.hpp). Inputs, told apart by their extension and header:
// - a scene (.json, docs/scene-format.md): its state after K steps (core/run/scene_state.hpp),
//   drawn with its handles; h is the scene's grid spacing;
// - a triangle mesh (.obj, .stl, or .ply or .off with faces): sampled at h with face normals;
// - a point set (.ply, .xyz, 2D or 3D): as read, with normals estimated (Pratt fit
//   over Delta) where the file has none.
// For files, h is given or estimated (see PictureInputOptions::spacing).
// A 2D picture also shows the MLS curve, the zero set of F of the points' AMLS
// surface (grid h, Delta = radius_factor h), traced by marching squares.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "core/run/scene_run.hpp"
#include "render/picture.hpp"

namespace amls {

// PictureInputOptions::step for a scene's state after its whole history.
constexpr std::size_t kFinalStep = std::numeric_limits<std::size_t>::max();

struct PictureInputOptions {
  // Scenes only: the state after this many steps (kFinalStep: after all of them); none: 0.
  std::optional<std::size_t> step;
  // Point sets and meshes only: h, the sampling spacing (splat size, normal length and
  // quality are in its units; a mesh is sampled at it): `spacing`, else `grid` cells as
  // `amls resample` counts them (core/run/point_set_resampling.hpp), else a point set's
  // h by the rule of core/geometry/sample_spacing.hpp, a mesh's bounding-box diagonal / 200.
  double spacing = 0.0;
  int grid = 0;
  double radius_factor = 3.0;  // Delta = radius_factor h: the MLS curve (2D), normal estimation
  int dimension = 0;           // point sets only: 0 decides from the file, 2 or 3 forces it
  int threads = 1;
  bool curve = true;       // 2D: trace the MLS curve
  bool quality = false;    // compute each point's nearest-neighbour spacing in units of h
  SceneProgress progress;  // scenes: called after every step of the run
};

// Reads `path` as above. Throws std::runtime_error naming the file for one that cannot
// be read, holds no points, or has a point with a non-finite position or normal or a
// zero normal; std::invalid_argument for options that do not fit the input (a step
// for a file, a spacing or dimension for a scene, a step past the scene's end).
Picture load_picture(const std::string& path, const PictureInputOptions& options);

}  // namespace amls
