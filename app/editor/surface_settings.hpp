#pragma once
// What the editor computes its surface with, and where the initial shape came
// from (as a scene says it: docs/scene-format.md). No GL.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/deform/mls_deformation.hpp"
#include "core/deform/region_handle.hpp"
#include "core/geometry/point_set.hpp"
#include "core/io/mesh_io.hpp"
#include "core/resample/resample_policy.hpp"
#include "core/resample/resampler.hpp"
#include "core/run/scene.hpp"

namespace amls::editor {

struct SurfaceSettings {
  double spacing = 0.024;      // grid spacing h
  double radius_factor = 3.0;  // Delta / h
  // Each point's own support, wider where the input is sparse
  // (AmlsParameters::widen_support): on for a point set opened on its own, as
  // `amls resample` does, else the scene's. Fixed for a session.
  bool widen_support = false;
  Variant variant = Variant::exact;
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
  bool resample = true;  // resample as `policy` says (off: only deform, and watch S(P) break)
  // Which steps resample, as `amls deform --resample` (core/resample/resample_policy.hpp).
  ResamplePolicy policy;

  bool operator==(const SurfaceSettings&) const = default;
  // The AMLS parameters of the surface these settings define.
  AmlsParameters parameters() const {
    AmlsParameters p;
    p.radius_factor = radius_factor;
    p.widen_support = widen_support;
    return p;
  }
  // Whether the grid (h, Delta / h) differs, which needs a new surface.
  bool same_grid(const SurfaceSettings& o) const { return spacing == o.spacing && radius_factor == o.radius_factor; }
};

// Throws std::invalid_argument naming the first field out of range.
void validate(const SurfaceSettings& settings);

// The initial shape as a scene's `shape` object says it (core/run/scene.hpp), in
// the shape's dimension, so that Save Scene writes back what was read: a torus
// stays a torus.
using ShapeSource = std::variant<SceneShape<2>, SceneShape<3>>;

// Region handles to start with, in the shape's dimension: kept as the scene
// made them (members, reach, motion, pin), so that a session started from a
// scene and saved again replays with the very same regions.
using StartRegions = std::variant<std::vector<RegionHandle<2>>, std::vector<RegionHandle<3>>>;

// Everything a session starts from.
struct InitialShape {
  PointSet<3> points;  // oriented; 2D sets have z = 0 and nz = 0
  ShapeSource source;
  SurfaceSettings settings;
  std::vector<Vec<3>> handles;  // handles to start with (a scene's first stage)
  StartRegions regions;         // region handles to start with (likewise)
  std::string name;             // shown in the title and messages
  std::vector<std::string> warnings;
  // A point-set file opened on its own: how well one resampling at h covers it,
  // as `amls resample` reports it ("" otherwise), and whether that is a clear loss.
  std::string coverage;
  bool coverage_loss = false;
  // A shape file opened on its own: what was read and done, and why h ("" otherwise).
  std::string opened;
  // A mesh file opened on its own, where it is closed and consistently wound
  // (SurfaceSamples::closed_mesh): its inside closes Export Mesh where F is
  // undefined, as `amls resample --mesh` does. Shared: shapes are copied.
  std::shared_ptr<const TriangleMesh> closed_mesh;

  // The source's dimension is the shape's: one fact, kept once.
  int dimension() const { return std::holds_alternative<SceneShape<2>>(source) ? 2 : 3; }
};

}  // namespace amls::editor
