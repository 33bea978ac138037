#pragma once
// The shapes a session starts from: built-in circles and spheres, point-set
// files and scenes (scene_start.hpp). No GL.
#include <cstddef>
#include <functional>
#include <string>

#include "app/editor/surface_settings.hpp"
#include "core/util/thread_pool.hpp"

namespace amls::editor {

// Built-in shapes centred at the origin with outward normals. Throws
// std::invalid_argument for a radius, count or spacing out of range.
InitialShape make_circle(double radius, std::size_t points, double spacing);
InitialShape make_sphere(double radius, std::size_t points, double spacing);

// What the editor opens without a file: the paper's circle of 250 points
// (h = 0.024, as the clover scene), or a sphere of 10 000 points (h = 0.04).
InitialShape default_shape(int dimension);

// Called before each step of a load, with its name, index and the count.
using LoadStep = std::function<void(const char* step, int index, int count)>;

// A shape file opened on its own - a point set (2D or 3D) with or without
// normals, or a triangle mesh - by the road `amls resample` takes
// (core/run/shape_opening.hpp): repaired, h by the rule of
// core/geometry/sample_spacing.hpp (rounded to 3 significant digits),
// missing normals estimated and oriented, a mesh sampled at h; supports
// widened where the points are sparse (AmlsParameters::widen_support), and
// the coverage of one resampling at h measured as `amls resample` measures
// it, with the same supports. Work runs on `pool`, whose cancel check stops
// it (Cancelled). With `estimate_normals` a point set's own normals are set
// aside and estimated (`amls resample --normals estimated`), and the session's
// scene says so, so that Save Scene replays it. Throws std::runtime_error
// naming the file for one that cannot be read, has too few points, or whose
// normals cannot be estimated.
InitialShape load_shape_file(const std::string& path, ThreadPool& pool, const LoadStep& step = {},
                             bool estimate_normals = false);

// A scene (.json) or a shape file, by the extension; the pool samples a
// scene's shape file (normal estimation, mesh sampling) too. A scene's own
// `normals` key decides for it: `estimate_normals` is for a shape file.
InitialShape load_initial_shape(const std::string& path, ThreadPool& pool, const LoadStep& step = {},
                                bool estimate_normals = false);
InitialShape load_initial_shape(const std::string& path, int threads);

// From this many points on, a shape the editor opens (built-in, file or
// scene) resamples under `local` rather than the paper's `always`: a whole
// resample takes over half a second a step there (0.6 s at 200k points, 3.5 s
// at 1M on two threads), a local step tens of milliseconds
// (docs/local-resampling.md). The Surface panel switches back.
inline constexpr std::size_t kLocalResamplingFrom = 100000;

}  // namespace amls::editor
