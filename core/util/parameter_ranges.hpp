#pragma once
// The allowed range of every numeric parameter, in one place: the command
// line's options, the scene reader's keys and the core's own checks use these,
// so a refused value gets the same message wherever it comes from - the key,
// the value and the range (docs/parameters.md lists them). The ranges keep the
// work bounded before it starts: no loop's trip count comes from an unchecked
// number.
#include <cstddef>
#include <string>

namespace amls {

struct ParameterRange {
  double min;
  double max;
  const char* meaning;  // what the number is, for the message (may be empty)

  bool contains(double value) const { return value >= min && value <= max; }  // false for NaN
};

namespace ranges {

// Delta / h. Below 1.5 a lone point's support (F is defined within 0.575 Delta
// of it) no longer reaches the vertices of the cell it lies in, and the surface
// vanishes within a few steps; above a few tens of h the neighbour queries only
// grow slower (their cost grows as (Delta / h)^D), not better. The hashing's
// cells are Delta wide, so this bound also bounds the cells a query visits.
inline constexpr ParameterRange kRadiusFactor{1.5, 32.0, "the influence radius Delta in units of h"};
// Cells per unit length (h = 1/N). The point count that a grid implies is
// checked on its own (kPoints).
inline constexpr ParameterRange kGridCells{1.0, 65536.0, "cells per unit length"};
// The flow tests' shapes (radius 0.15) need a few cells across.
inline constexpr ParameterRange kFlowTestGridCells{8.0, 65536.0, "cells per unit length"};
// The grid spacing h given directly, in the input's units; what it implies is
// bounded by the point counts.
inline constexpr ParameterRange kSpacing{1e-9, 1e9, "grid spacing h"};
// Points a shape is sampled with, or a run starts from.
inline constexpr ParameterRange kPoints{1.0, 2e7, "points"};
// A flow test's time between resamplings (periods are 8 and 3).
inline constexpr ParameterRange kTimeStep{1e-4, 1.0, "time between resamplings"};
inline constexpr ParameterRange kSubsteps{1.0, 1000.0, "RK4 steps per dt"};
// Steps of one handle target in a scene, and of a whole scene.
inline constexpr ParameterRange kTargetSteps{1.0, 100000.0, "steps"};
inline constexpr ParameterRange kSceneSteps{1.0, 1000000.0, "steps in all stages"};
inline constexpr ParameterRange kHandles{1.0, 1024.0, "handles in a stage"};
// Region handles: a scene's regions, and those one stage uses (each costs a
// nearest-member query and D + 1 handles in every point's MLS map).
inline constexpr ParameterRange kRegions{1.0, 64.0, "regions"};
inline constexpr ParameterRange kStageRegions{0.0, 64.0, "regions in a stage"};
// A region handle's uniform scale.
inline constexpr ParameterRange kRegionScale{1e-3, 1e3, "a region's scale"};
// The MLS deformation's weights |p_i - v|^(-2 alpha).
inline constexpr ParameterRange kAlpha{0.1, 10.0, "the MLS deformation's weight exponent"};
inline constexpr ParameterRange kTracersPerPoint{1.0, 1000.0, "tracer points per initial point"};
inline constexpr ParameterRange kMinWeight{0.0, 10.0, "the least sum of weights where F is defined"};
inline constexpr ParameterRange kThreads{1.0, 256.0, "threads"};
inline constexpr ParameterRange kRaySamples{1.0, 64.0, "samples of F per cell along a ray"};
inline constexpr ParameterRange kClusterThreshold{0.0, 1.0, "cluster distance in units of h"};
inline constexpr ParameterRange kFramesEvery{1.0, 1000000.0, "steps between written frames"};
// One side of an image, in pixels (also the largest offscreen buffer OSMesa is asked for).
inline constexpr ParameterRange kImageSide{1.0, 16384.0, "pixels"};
inline constexpr ParameterRange kSupersample{1.0, 8.0, "samples per pixel along each side"};
// Samples a mesh may be turned into (core/io/mesh_sampling.hpp).
inline constexpr ParameterRange kMeshSamples{1.0, 2e7, "mesh samples"};

}  // namespace ranges

// "must be within [MIN, MAX] (MEANING), got VALUE": the text that follows a
// refused value's key, in every message.
std::string out_of_range_text(double value, const ParameterRange& range);
// Throws std::invalid_argument "KEY: must be within ..." if `value` is outside
// `range` (or NaN).
void check_range(const std::string& key, double value, const ParameterRange& range);

// A number as messages print it: up to 6 significant digits, no trailing zeros.
std::string format_number(double value);

struct ImageSize {
  int width = 0;
  int height = 0;
};

// "WxH" (or "WXH"), e.g. "480x360", each side a whole number in
// [min_side, ranges::kImageSide.max]. Throws std::invalid_argument naming
// `key`, the text and the range otherwise.
ImageSize parse_image_size(const std::string& text, const std::string& key, int min_side = 1);

}  // namespace amls
