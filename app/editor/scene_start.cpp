#include "app/editor/scene_start.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "app/editor/initial_shape.hpp"

namespace amls::editor {

namespace {

using nlohmann::json;

// Reads values from one scene file, naming the file and the key in every error.
class SceneReader {
 public:
  explicit SceneReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::runtime_error(path_ + ": " + key + ": " + what);
  }

  const json& object(const json& parent, const std::string& key) const {
    if (!parent.contains(key)) fail(key, "missing");
    if (!parent[key].is_object()) fail(key, "must be an object");
    return parent[key];
  }

  double number(const json& parent, const std::string& key, double fallback) const {
    if (!parent.contains(key)) return fallback;
    if (!parent[key].is_number()) fail(key, "must be a number");
    return parent[key].get<double>();
  }

  double positive(const json& parent, const std::string& key, double fallback) const {
    const double value = number(parent, key, fallback);
    if (!(value > 0.0) || !std::isfinite(value)) fail(key, "must be a positive number");
    return value;
  }

  std::string text(const json& parent, const std::string& key, const std::string& fallback) const {
    if (!parent.contains(key)) return fallback;
    if (!parent[key].is_string()) fail(key, "must be a string");
    return parent[key].get<std::string>();
  }

  // An array of `dimension` numbers, as a 3D vector (z = 0 in 2D).
  Vec<3> point(const json& value, int dimension, const std::string& key) const {
    if (!value.is_array() || static_cast<int>(value.size()) != dimension)
      fail(key, "must be an array of " + std::to_string(dimension) + " numbers");
    Vec<3> p = Vec<3>::Zero();
    for (int a = 0; a < dimension; ++a) {
      if (!value[static_cast<std::size_t>(a)].is_number()) fail(key, "must hold numbers");
      p[a] = value[static_cast<std::size_t>(a)].get<double>();
    }
    return p;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

json parse_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the scene file");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
}

// Circle and sphere point counts for a spacing, when a scene gives `spacing`
// rather than `points`: the circumference, or a hexagonal lattice over the area.
std::size_t points_for_spacing(int dimension, double radius, double spacing) {
  const double count = dimension == 2 ? 2.0 * std::numbers::pi * radius / spacing
                                      : 4.0 * std::numbers::pi * radius * radius / (spacing * spacing * 0.8660254);
  return std::max<std::size_t>(dimension == 2 ? 3 : 4, static_cast<std::size_t>(std::llround(count)));
}

InitialShape read_shape(const SceneReader& r, const json& scene, int dimension, double h) {
  const json& shape = r.object(scene, "shape");
  const std::string type = r.text(shape, "type", "");
  if (type == "file") {
    const std::string file = r.text(shape, "path", "");
    if (file.empty()) r.fail("shape.path", "missing");
    const std::filesystem::path resolved = std::filesystem::path(r.path()).parent_path() / file;
    InitialShape loaded = load_point_set_file(resolved.lexically_normal().string());
    if (loaded.dimension != dimension)
      r.fail("shape.path", file + " holds a " + std::to_string(loaded.dimension) + "D set, but the scene is " +
                               std::to_string(dimension) + "D");
    return loaded;
  }
  const bool round = (type == "circle" && dimension == 2) || (type == "sphere" && dimension == 3);
  if (!round) {
    if (type == "circle" || type == "sphere")
      r.fail("shape.type", type + " needs dimension " + (type == "circle" ? "2" : "3"));
    r.fail("shape.type", "'" + type +
                             "' is not one the editor builds yet (circle, sphere and file are; the others come "
                             "with core/scene.hpp)");
  }
  const double radius = r.positive(shape, "radius", 1.0);
  std::size_t count = 0;
  if (shape.contains("points")) {
    if (!shape["points"].is_number_unsigned()) r.fail("shape.points", "must be a positive whole number");
    count = shape["points"].get<std::size_t>();
  } else {
    count = points_for_spacing(dimension, radius, r.positive(shape, "spacing", h));
  }
  InitialShape out = dimension == 2 ? make_circle(radius, count, h) : make_sphere(radius, count, h);
  if (shape.contains("center")) {
    const Vec<3> center = r.point(shape["center"], dimension, "shape.center");
    for (Vec<3>& p : out.points.positions) p += center;
    out.source.center = center;
  }
  return out;
}

double read_spacing(const SceneReader& r, const json& scene) {
  const json& grid = r.object(scene, "grid");
  if (grid.contains("cells") == grid.contains("spacing")) r.fail("grid", "needs exactly one of 'cells' and 'spacing'");
  if (grid.contains("spacing")) return r.positive(grid, "spacing", 0.0);
  if (!grid["cells"].is_number_unsigned() || grid["cells"].get<std::size_t>() == 0)
    r.fail("grid.cells", "must be a positive whole number");
  return 1.0 / static_cast<double>(grid["cells"].get<std::size_t>());
}

}  // namespace

InitialShape load_scene_start(const std::string& path) {
  const SceneReader r(path);
  const json scene = parse_file(path);
  if (!scene.is_object()) r.fail("(top level)", "must be an object");
  if (!scene.contains("dimension") || !scene["dimension"].is_number_integer()) r.fail("dimension", "must be 2 or 3");
  const int dimension = scene["dimension"].get<int>();
  if (dimension != 2 && dimension != 3) r.fail("dimension", "must be 2 or 3");

  SurfaceSettings settings;
  settings.spacing = read_spacing(r, scene);
  settings.radius_factor = r.positive(scene, "radius_factor", 3.0);
  try {
    settings.variant = parse_variant(r.text(scene, "variant", "exact"));
  } catch (const std::invalid_argument& e) {
    r.fail("variant", e.what());
  }
  if (scene.contains("deformation")) {
    const json& deformation = r.object(scene, "deformation");
    try {
      settings.kind = parse_mls_kind(r.text(deformation, "kind", "rigid"));
    } catch (const std::invalid_argument& e) {
      r.fail("deformation.kind", e.what());
    }
    settings.alpha = r.positive(deformation, "alpha", 1.0);
  }

  InitialShape shape = read_shape(r, scene, dimension, settings.spacing);
  shape.settings = settings;
  if (scene.contains("stages") && scene["stages"].is_array() && !scene["stages"].empty()) {
    const json& first = scene["stages"][0];
    if (first.is_object() && first.contains("handles")) {
      if (!first["handles"].is_array()) r.fail("stages[0].handles", "must be an array of points");
      for (std::size_t i = 0; i < first["handles"].size(); ++i)
        shape.handles.push_back(
            r.point(first["handles"][i], dimension, "stages[0].handles[" + std::to_string(i) + "]"));
    }
  }
  const std::string name = r.text(scene, "name", "");
  shape.name = name.empty() ? std::filesystem::path(path).filename().string() : name;
  return shape;
}

}  // namespace amls::editor
