#pragma once
// Scenes (docs/scene-format.md): a JSON file that says what to deform and how
// - the dimension, the initial shape (built in, or a point-set or mesh file),
// the grid, the AMLS parameters, the MLS deformation's kind and alpha, and the
// deformation history as handle stages. Scenes, the editor's Save Scene and
// `amls deform` share this one format.
#include <cstddef>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <variant>

#include "core/deform/deformation_history.hpp"
#include "core/deform/mls_deformation.hpp"
#include "core/resample/resampler.hpp"

namespace amls {

enum class ShapeType { circle, ellipse, sphere, torus, rounded_box, file };

const char* to_string(ShapeType type);

template <int D>
struct SceneShape {
  ShapeType type = D == 2 ? ShapeType::circle : ShapeType::sphere;
  Vec<D> center = Vec<D>::Zero();
  double radius = 1.0;                           // circle, sphere; rounded_box: the corner radius
  Vec<D> semi_axes = Vec<D>::Ones();             // ellipse
  Vec<D> half_extents = Vec<D>::Constant(0.5);   // rounded_box
  double major_radius = 1.0;                     // torus (about the z axis)
  double minor_radius = 0.25;                    // torus
  std::size_t points = 0;                        // circle, sphere: this many points (0: from the spacing)
  double spacing = 0.0;                          // distance between samples; 0: the grid spacing h
  std::string file;                              // file: as written in the scene (relative to it)
  std::string resolved_file;                     // file: the path to open
  // file: a point set's own normals set aside and estimated (`"normals": "estimated"`,
  // SurfaceSampleOptions::estimate_normals).
  bool estimate_normals = false;
};

template <int D>
struct Scene {
  std::string path;  // the file it was read from, for messages ("" if built in code)
  std::string name;
  std::string description;
  SceneShape<D> shape;
  int grid_cells = 0;         // h = 1 / grid_cells, if set
  double grid_spacing = 0.0;  // h itself, if set (exactly one of the two is set)
  // A file shape's scene without a grid: grid_spacing was measured on the file
  // (core/geometry/sample_spacing.hpp).
  bool grid_from_file = false;
  double radius_factor = 3.0;
  // Each point's own support, wider where the input is sparse
  // (AmlsParameters::widen_support); the editor sets it for a point set it
  // opens on its own, as `amls resample` widens.
  bool widen_support = false;
  bool keep_rims = AmlsParameters{}.keep_rims;  // AmlsParameters::keep_rims (`amls deform --rims`)
  Variant variant = Variant::exact;
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
  DeformationHistory<D> history;

  // The AMLS parameters the scene's surface is defined with.
  AmlsParameters parameters() const {
    AmlsParameters p;
    p.radius_factor = radius_factor;
    p.widen_support = widen_support;
    p.keep_rims = keep_rims;
    return p;
  }
  double h() const { return grid_spacing > 0.0 ? grid_spacing : 1.0 / grid_cells; }
  // The spacing of the initial samples (the shape's own, else h).
  double sample_spacing() const { return shape.spacing > 0.0 ? shape.spacing : h(); }
};

// A scene of either dimension, as read from a file.
using AnyScene = std::variant<Scene<2>, Scene<3>>;

// Reads and checks a scene file. Throws std::runtime_error naming the file and
// the key's place in it (`path: stages[1].targets[0].handles: ...`) for a file
// that cannot be read, invalid JSON, an unknown key, a value of the wrong type
// or out of range, a non-finite number, a handle count that changes inside a
// stage, or a shape file that does not exist.
AnyScene read_scene(const std::string& path);
// The same from JSON already parsed; `path` names it in messages and relative
// shape files are resolved against its folder.
AnyScene scene_from_json(const nlohmann::json& json, const std::string& path);

// The scene as JSON that scene_from_json reads back to the same scene.
template <int D>
nlohmann::json to_json(const Scene<D>& scene);
// Writes it through a temporary file renamed into place.
template <int D>
void write_scene(const std::string& path, const Scene<D>& scene);

extern template nlohmann::json to_json<2>(const Scene<2>&);
extern template nlohmann::json to_json<3>(const Scene<3>&);
extern template void write_scene<2>(const std::string&, const Scene<2>&);
extern template void write_scene<3>(const std::string&, const Scene<3>&);

}  // namespace amls
