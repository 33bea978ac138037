#include "core/run/scene.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

#include "core/geometry/sample_spacing.hpp"
#include "core/geometry/shapes.hpp"
#include "core/io/file_format.hpp"
#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "core/io/surface_samples.hpp"
#include "core/util/file_error.hpp"
#include "core/util/parameter_ranges.hpp"

namespace amls {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::initializer_list<ShapeType> kShapeTypes = {ShapeType::circle, ShapeType::ellipse,     ShapeType::sphere,
                                                          ShapeType::torus,  ShapeType::rounded_box, ShapeType::file};

// Where a value stands in the scene file, for messages: `stages[1].targets[0]`.
class Place {
 public:
  Place(const std::string& file, std::string where) : file_(&file), where_(std::move(where)) {}
  Place key(const std::string& name) const { return Place(*file_, where_.empty() ? name : where_ + "." + name); }
  Place index(std::size_t i) const { return Place(*file_, where_ + "[" + std::to_string(i) + "]"); }
  const std::string& where() const { return where_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(*file_ + ": " + (where_.empty() ? "" : where_ + ": ") + what);
  }
  // A file the scene names that is not there: the same message, as the
  // FileError of `error` (ENOENT, EISDIR), which tells it from wrong contents.
  [[noreturn]] void fail_file(const std::string& what, int error) const {
    throw FileError(*file_ + ": " + (where_.empty() ? "" : where_ + ": ") + what, error);
  }
  // For a message that names its place itself.
  [[noreturn]] void fail_in_file(const std::string& what) const { throw std::runtime_error(*file_ + ": " + what); }

 private:
  const std::string* file_;
  std::string where_;
};

std::string type_name(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    default:
      return "a number";
  }
}

double as_number(const json& j, const Place& at) {
  if (!j.is_number()) at.fail("expected a number, got " + type_name(j));
  const double value = j.get<double>();
  if (!std::isfinite(value)) at.fail("not a finite number");
  return value;
}

double as_positive(const json& j, const Place& at) {
  const double value = as_number(j, at);
  if (!(value > 0.0)) at.fail("must be positive, got " + format_number(value));
  return value;
}

// A number within `range` (core/util/parameter_ranges.hpp), with the command line's message.
double as_in_range(const json& j, const Place& at, const ParameterRange& range) {
  const double value = as_number(j, at);
  if (!range.contains(value)) at.fail(out_of_range_text(value, range));
  return value;
}

// A whole number within `range`.
std::size_t as_count(const json& j, const Place& at, const ParameterRange& range) {
  if (!j.is_number_integer()) at.fail("expected a whole number, got " + (j.is_number() ? j.dump() : type_name(j)));
  const double value =
      j.is_number_unsigned() ? static_cast<double>(j.get<std::uint64_t>()) : static_cast<double>(j.get<std::int64_t>());
  if (!range.contains(value)) at.fail(out_of_range_text(value, range));
  return static_cast<std::size_t>(value);
}

// Refuses a non-finite number anywhere in the file, read or not, naming its
// place (JSON has no literal for one, but 1e999 parses to infinity).
void check_finite_numbers(const json& j, const Place& at) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) at.fail("not a finite number");
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) check_finite_numbers(j[i], at.index(i));
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) check_finite_numbers(it.value(), at.key(it.key()));
}

bool as_bool(const json& j, const Place& at) {
  if (!j.is_boolean()) at.fail("expected true or false, got " + (j.is_number() ? j.dump() : type_name(j)));
  return j.get<bool>();
}

std::string as_string(const json& j, const Place& at) {
  if (!j.is_string()) at.fail("expected a string, got " + type_name(j));
  return j.get<std::string>();
}

template <int D>
Vec<D> as_vec(const json& j, const Place& at) {
  if (!j.is_array() || j.size() != static_cast<std::size_t>(D))
    at.fail("expected an array of " + std::to_string(D) + " numbers (the scene is " + std::to_string(D) + "D), got " +
            (j.is_array() ? "an array of " + std::to_string(j.size()) : type_name(j)));
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = as_number(j[static_cast<std::size_t>(a)], at.index(static_cast<std::size_t>(a)));
  return v;
}

template <int D>
std::vector<Vec<D>> as_points(const json& j, const Place& at) {
  if (!j.is_array()) at.fail("expected an array of points, got " + type_name(j));
  std::vector<Vec<D>> out;
  for (std::size_t i = 0; i < j.size(); ++i) out.push_back(as_vec<D>(j[i], at.index(i)));
  return out;
}

// An object whose keys are read one by one; finish() rejects the ones no reader asked for.
class ObjectReader {
 public:
  ObjectReader(const json& j, Place at) : j_(j), at_(std::move(at)) {
    if (!j.is_object()) at_.fail("expected an object, got " + type_name(j));
  }
  const Place& place() const { return at_; }

  const json* find(const std::string& key) {
    known_.push_back(key);
    const auto it = j_.find(key);
    return it == j_.end() ? nullptr : &*it;
  }
  const json& require(const std::string& key) {
    const json* value = find(key);
    if (!value) at_.fail("missing the required key '" + key + "'");
    return *value;
  }
  // Marks keys as known without reading them (they belong to another branch).
  void allow(std::initializer_list<const char*> keys) { known_.insert(known_.end(), keys.begin(), keys.end()); }

  void finish() const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
      std::string expected;
      for (std::size_t k = 0; k < known_.size(); ++k)
        expected += (k == 0 ? "" : k + 1 == known_.size() ? " or " : ", ") + known_[k];
      at_.key(it.key()).fail("unknown key (expected " + expected + ")");
    }
  }

 private:
  const json& j_;
  Place at_;
  std::vector<std::string> known_;
};

ShapeType parse_shape_type(const std::string& name, const Place& at) {
  for (ShapeType type : kShapeTypes)
    if (name == to_string(type)) return type;
  at.fail("unknown shape '" + name + "' (expected circle, ellipse, sphere, torus, rounded_box or file)");
}

template <int D>
SceneShape<D> parse_shape(const json& j, const Place& at, const std::string& scene_path) {
  ObjectReader r(j, at);
  SceneShape<D> shape;
  const Place type_at = at.key("type");
  shape.type = parse_shape_type(as_string(r.require("type"), type_at), type_at);
  const bool plane_only = shape.type == ShapeType::circle || shape.type == ShapeType::ellipse;
  const bool space_only = shape.type == ShapeType::sphere || shape.type == ShapeType::torus;
  if ((plane_only && D != 2) || (space_only && D != 3))
    type_at.fail(std::string("a ") + to_string(shape.type) + " is a " + (plane_only ? "2D" : "3D") +
                 " shape, but the scene's dimension is " + std::to_string(D));
  if (const json* v = r.find("spacing")) shape.spacing = as_in_range(*v, at.key("spacing"), ranges::kSpacing);
  auto read_center = [&] {
    if (const json* v = r.find("center")) shape.center = as_vec<D>(*v, at.key("center"));
  };
  auto read_radius = [&] {
    if (const json* v = r.find("radius")) shape.radius = as_positive(*v, at.key("radius"));
  };
  auto read_points = [&](double least) {
    if (const json* v = r.find("points")) {
      if (shape.spacing > 0.0) at.key("points").fail("give either 'points' or 'spacing', not both");
      shape.points =
          as_count(*v, at.key("points"), ParameterRange{least, ranges::kPoints.max, ranges::kPoints.meaning});
    }
  };
  auto positive_vec = [&](const char* key) {
    const Vec<D> v = as_vec<D>(r.require(key), at.key(key));
    for (int a = 0; a < D; ++a)
      if (!(v[a] > 0.0))
        at.key(key).index(static_cast<std::size_t>(a)).fail("must be positive, got " + format_number(v[a]));
    return v;
  };
  switch (shape.type) {
    case ShapeType::circle:
    case ShapeType::sphere:
      read_center();
      read_radius();
      read_points(shape.type == ShapeType::circle ? 3 : 4);
      break;
    case ShapeType::ellipse:
      read_center();
      shape.semi_axes = positive_vec("semi_axes");
      break;
    case ShapeType::torus:
      read_center();
      shape.major_radius = as_positive(r.require("major_radius"), at.key("major_radius"));
      shape.minor_radius = as_positive(r.require("minor_radius"), at.key("minor_radius"));
      if (!(shape.minor_radius < shape.major_radius))
        at.key("minor_radius").fail("must be smaller than major_radius (" + format_number(shape.major_radius) + ")");
      break;
    case ShapeType::rounded_box:
      read_center();
      shape.half_extents = positive_vec("half_extents");
      shape.radius = as_number(r.require("radius"), at.key("radius"));
      if (!(shape.radius >= 0.0) || shape.radius > shape.half_extents.minCoeff())
        at.key("radius").fail("the corner radius must lie in [0, smallest half extent = " +
                              format_number(shape.half_extents.minCoeff()) + "], got " + format_number(shape.radius));
      break;
    case ShapeType::file: {
      const Place path_at = at.key("path");
      shape.file = as_string(r.require("path"), path_at);
      if (shape.file.empty()) path_at.fail("empty file name");
      const fs::path base = fs::path(scene_path).parent_path();
      shape.resolved_file =
          (fs::path(shape.file).is_absolute() ? fs::path(shape.file) : base / shape.file).lexically_normal().string();
      if (!shape_file_format(shape.file))
        path_at.fail("unknown file type '" + lower_extension(shape.file) + "' (expected " + kShapeFileExtensions + ")");
      if (const json* v = r.find("normals")) {
        const std::string normals = as_string(*v, at.key("normals"));
        if (normals != "given" && normals != "estimated")
          at.key("normals").fail("expected \"given\" or \"estimated\", got \"" + normals + "\"");
        shape.estimate_normals = normals == "estimated";
      }
      std::error_code error;
      if (fs::is_directory(shape.resolved_file, error))
        path_at.fail_file("is a directory, not a shape file: " + shape.resolved_file, EISDIR);
      if (!fs::is_regular_file(shape.resolved_file, error))
        path_at.fail_file("no such file: " + shape.resolved_file + " (paths are relative to the scene file)", ENOENT);
      break;
    }
  }
  r.finish();
  return shape;
}

// The length (2D) or area (3D) of a built-in shape, or an upper bound of it; 0 for a file.
template <int D>
double shape_measure(const SceneShape<D>& s) {
  constexpr double pi = std::numbers::pi;
  switch (s.type) {
    case ShapeType::circle:
      return 2.0 * pi * s.radius;
    case ShapeType::sphere:
      return 4.0 * pi * s.radius * s.radius;
    case ShapeType::ellipse:
      return 2.0 * pi * s.semi_axes.maxCoeff();
    case ShapeType::torus:
      return 4.0 * pi * pi * s.major_radius * s.minor_radius;
    case ShapeType::rounded_box: {
      const Vec<D> e = s.half_extents;
      if constexpr (D == 2)
        return 4.0 * (e[0] + e[1]);
      else
        return 8.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
    }
    case ShapeType::file:
      break;
  }
  return 0.0;
}

// Refuses a built-in shape whose samples, or the points resampling it at h
// makes (about one per cell it crosses), would be more than ranges::kPoints
// allows, before any is made.
template <int D>
void check_point_estimate(const Scene<D>& scene, const Place& at) {
  const double measure = shape_measure(scene.shape);
  const double initial = scene.shape.points > 0 ? static_cast<double>(scene.shape.points)
                                                : measure / std::pow(scene.sample_spacing(), D - 1);
  const double resampled = measure / std::pow(scene.h(), D - 1);
  const double estimate = std::max(initial, resampled);
  if (estimate <= ranges::kPoints.max) return;
  const double fitting =
      std::max(scene.sample_spacing(), scene.h()) * std::pow(estimate / ranges::kPoints.max, 1.0 / (D - 1));
  at.fail("sampling this " + std::string(to_string(scene.shape.type)) + " at spacing " +
          format_number(scene.sample_spacing()) + " and resampling it at h = " + format_number(scene.h()) +
          " makes about " + format_number(estimate) + " points, more than " + format_number(ranges::kPoints.max) +
          "; a spacing and h of " + format_number(fitting) + " or more would fit");
}

// A region handle's motion: {"translation": [...], "rotation": angle (2D) or
// rotation vector (3D), "scale": s}, each key optional (the identity).
template <int D>
RegionMotion<D> parse_motion(const json& j, const Place& at) {
  ObjectReader r(j, at);
  RegionMotion<D> motion;
  if (const json* v = r.find("translation")) motion.translation = as_vec<D>(*v, at.key("translation"));
  if (const json* v = r.find("rotation")) {
    if constexpr (D == 2)
      motion.rotation[0] = as_number(*v, at.key("rotation"));
    else
      motion.rotation = as_vec<3>(*v, at.key("rotation"));
  }
  if (const json* v = r.find("scale")) motion.scale = as_in_range(*v, at.key("scale"), ranges::kRegionScale);
  r.finish();
  return motion;
}

// The scene's regions: each {"points": [...], "reach": r} (reach: h unless given).
template <int D>
std::vector<std::shared_ptr<const PointRegion<D>>> parse_regions(const json& j, const Place& at, double h) {
  if (!j.is_array()) at.fail("expected an array of regions, got " + type_name(j));
  if (!ranges::kRegions.contains(static_cast<double>(j.size())))
    at.fail(out_of_range_text(static_cast<double>(j.size()), ranges::kRegions));
  std::vector<std::shared_ptr<const PointRegion<D>>> regions;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const Place region_at = at.index(i);
    ObjectReader r(j[i], region_at);
    const json& points = r.require("points");
    if (points.is_array() && !ranges::kPoints.contains(static_cast<double>(points.size())))
      region_at.key("points").fail(out_of_range_text(static_cast<double>(points.size()), ranges::kPoints));
    std::vector<Vec<D>> members = as_points<D>(points, region_at.key("points"));
    double reach = h;
    if (const json* v = r.find("reach")) reach = as_in_range(*v, region_at.key("reach"), ranges::kSpacing);
    r.finish();
    regions.push_back(std::make_shared<const PointRegion<D>>(std::move(members), reach));
  }
  return regions;
}

// A stage's region handles: [{"region": index, "pinned": bool, "motion": {...}}].
template <int D>
std::vector<RegionHandle<D>> parse_stage_regions(const json& j, const Place& at,
                                                 const std::vector<std::shared_ptr<const PointRegion<D>>>& regions) {
  if (!j.is_array()) at.fail("expected an array of region handles, got " + type_name(j));
  if (!ranges::kStageRegions.contains(static_cast<double>(j.size())))
    at.fail(out_of_range_text(static_cast<double>(j.size()), ranges::kStageRegions));
  std::vector<RegionHandle<D>> out;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const Place handle_at = at.index(i);
    ObjectReader r(j[i], handle_at);
    if (regions.empty()) handle_at.fail("the scene defines no 'regions' to refer to");
    const std::size_t index = as_count(r.require("region"), handle_at.key("region"),
                                       ParameterRange{0, static_cast<double>(regions.size() - 1), "a region's index"});
    for (const RegionHandle<D>& earlier : out)
      if (earlier.region == regions[index])
        handle_at.key("region").fail("region " + std::to_string(index) + " is in this stage twice");
    RegionHandle<D> handle{regions[index], {}, false};
    if (const json* v = r.find("pinned")) handle.pinned = as_bool(*v, handle_at.key("pinned"));
    if (const json* v = r.find("motion")) handle.motion = parse_motion<D>(*v, handle_at.key("motion"));
    r.finish();
    out.push_back(std::move(handle));
  }
  return out;
}

template <int D>
DeformationHistory<D> parse_stages(const json& j, const Place& at,
                                   const std::vector<std::shared_ptr<const PointRegion<D>>>& regions) {
  if (!j.is_array()) at.fail("expected an array of stages, got " + type_name(j));
  if (j.empty()) at.fail("the history has no stage");
  DeformationHistory<D> history;
  for (std::size_t s = 0; s < j.size(); ++s) {
    const Place stage_at = at.index(s);
    ObjectReader stage(j[s], stage_at);
    std::vector<RegionHandle<D>> stage_regions;
    if (const json* v = stage.find("regions"))
      stage_regions = parse_stage_regions<D>(*v, stage_at.key("regions"), regions);
    history.begin_stage(as_points<D>(stage.require("handles"), stage_at.key("handles")), stage_regions);
    const std::size_t handles = history.stages.back().start.size();
    // A stage moved by regions alone may have no point handle.
    const ParameterRange handle_range =
        stage_regions.empty() ? ranges::kHandles : ParameterRange{0.0, ranges::kHandles.max, ranges::kHandles.meaning};
    if (!handle_range.contains(static_cast<double>(handles)))
      stage_at.key("handles").fail(out_of_range_text(static_cast<double>(handles), handle_range));
    const json& targets = stage.require("targets");
    const Place targets_at = stage_at.key("targets");
    if (!targets.is_array()) targets_at.fail("expected an array of targets, got " + type_name(targets));
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const Place target_at = targets_at.index(t);
      ObjectReader target(targets[t], target_at);
      HandleTarget<D> next;
      next.handles = as_points<D>(target.require("handles"), target_at.key("handles"));
      next.steps = as_count(target.require("steps"), target_at.key("steps"), ranges::kTargetSteps);
      if (!stage_regions.empty()) {
        const Place motions_at = target_at.key("regions");
        const json& motions = target.require("regions");
        if (!motions.is_array()) motions_at.fail("expected an array of region motions, got " + type_name(motions));
        if (motions.size() != stage_regions.size())
          motions_at.fail(std::to_string(motions.size()) + " motions, but the stage has " +
                          std::to_string(stage_regions.size()) +
                          " regions (adding or removing a region starts a new stage)");
        for (std::size_t m = 0; m < motions.size(); ++m)
          next.regions.push_back(parse_motion<D>(motions[m], motions_at.index(m)));
      }
      target.finish();
      history.stages.back().targets.push_back(std::move(next));
    }
    stage.finish();
  }
  try {
    history.validate();
  } catch (const std::invalid_argument& e) {
    // Its messages name the place (stages[i]...) already.
    at.fail_in_file(e.what());
  }
  const double steps = static_cast<double>(history.total_steps());
  if (!ranges::kSceneSteps.contains(steps)) at.fail(out_of_range_text(steps, ranges::kSceneSteps));
  return history;
}

// h for a file shape without a grid: the rule of core/geometry/sample_spacing.hpp
// on the file's points (a mesh's vertices), as `amls resample` and the editor choose it.
template <int D>
double spacing_of_file(const std::string& file, const Place& at) {
  try {
    const SurfaceInput input = read_surface_input(file, D);
    return sample_spacing<D>(from_3d<D>(input.positions()), input.recorded_spacing()).h;
  } catch (const std::exception& e) {
    at.fail(std::string("no 'grid' given, and h cannot be measured on the file: ") + e.what());
  }
}

template <int D>
Scene<D> parse_scene(const json& j, const std::string& path) {
  Scene<D> scene;
  scene.path = path;
  const Place root(scene.path, "");
  ObjectReader r(j, root);
  r.allow({"dimension"});
  if (const json* v = r.find("name")) scene.name = as_string(*v, root.key("name"));
  if (const json* v = r.find("description")) scene.description = as_string(*v, root.key("description"));
  const json* grid_json = r.find("grid");
  if (grid_json) {
    const Place grid_at = root.key("grid");
    ObjectReader grid(*grid_json, grid_at);
    const json* cells = grid.find("cells");
    const json* spacing = grid.find("spacing");
    if ((cells == nullptr) == (spacing == nullptr))
      grid_at.fail("give exactly one of 'cells' (h = 1/cells) or 'spacing' (h)");
    if (cells) scene.grid_cells = static_cast<int>(as_count(*cells, grid_at.key("cells"), ranges::kGridCells));
    if (spacing) scene.grid_spacing = as_in_range(*spacing, grid_at.key("spacing"), ranges::kSpacing);
    grid.finish();
  }
  scene.shape = parse_shape<D>(r.require("shape"), root.key("shape"), path);
  if (!grid_json) {
    if (scene.shape.type != ShapeType::file)
      root.fail("missing the required key 'grid' (only a file shape may leave it out: h then comes from the file)");
    scene.grid_spacing = spacing_of_file<D>(scene.shape.resolved_file, root.key("shape").key("path"));
    scene.grid_from_file = true;
  }
  check_point_estimate(scene, root.key("shape"));
  if (const json* v = r.find("radius_factor"))
    scene.radius_factor = as_in_range(*v, root.key("radius_factor"), ranges::kRadiusFactor);
  if (const json* v = r.find("widen_support")) scene.widen_support = as_bool(*v, root.key("widen_support"));
  if (const json* v = r.find("variant")) {
    try {
      scene.variant = parse_variant(as_string(*v, root.key("variant")));
    } catch (const std::invalid_argument& e) {
      root.key("variant").fail(e.what());
    }
  }
  if (const json* v = r.find("deformation")) {
    const Place at = root.key("deformation");
    ObjectReader deformation(*v, at);
    if (const json* kind = deformation.find("kind")) {
      try {
        scene.kind = parse_mls_kind(as_string(*kind, at.key("kind")));
      } catch (const std::invalid_argument& e) {
        at.key("kind").fail(e.what());
      }
    }
    if (const json* alpha = deformation.find("alpha"))
      scene.alpha = as_in_range(*alpha, at.key("alpha"), ranges::kAlpha);
    deformation.finish();
  }
  std::vector<std::shared_ptr<const PointRegion<D>>> regions;
  if (const json* v = r.find("regions")) {
    try {
      regions = parse_regions<D>(*v, root.key("regions"), scene.h());
    } catch (const std::invalid_argument& e) {
      root.key("regions").fail(e.what());
    }
  }
  scene.history = parse_stages<D>(r.require("stages"), root.key("stages"), regions);
  r.finish();
  return scene;
}

template <int D>
json points_json(const std::vector<Vec<D>>& points) {
  json out = json::array();
  for (const Vec<D>& p : points) {
    json v = json::array();
    for (int a = 0; a < D; ++a) v.push_back(p[a]);
    out.push_back(std::move(v));
  }
  return out;
}

template <int D>
json vec_json(const Vec<D>& v) {
  return points_json<D>({v})[0];
}

template <int D>
json motion_json(const RegionMotion<D>& motion) {
  json out = json::object();
  if (!motion.translation.isZero(0.0)) out["translation"] = vec_json<D>(motion.translation);
  if (!motion.rotation.isZero(0.0)) {
    if constexpr (D == 2)
      out["rotation"] = motion.rotation[0];
    else
      out["rotation"] = vec_json<3>(motion.rotation);
  }
  if (motion.scale != 1.0) out["scale"] = motion.scale;
  return out;
}

}  // namespace

const char* to_string(ShapeType type) {
  switch (type) {
    case ShapeType::circle:
      return "circle";
    case ShapeType::ellipse:
      return "ellipse";
    case ShapeType::sphere:
      return "sphere";
    case ShapeType::torus:
      return "torus";
    case ShapeType::rounded_box:
      return "rounded_box";
    case ShapeType::file:
      return "file";
  }
  return "?";
}

AnyScene scene_from_json(const json& j, const std::string& path) {
  const Place root(path, "");
  if (!j.is_object()) root.fail("expected a JSON object at the top, got " + type_name(j));
  const auto it = j.find("dimension");
  if (it == j.end()) root.fail("missing the required key 'dimension' (2 or 3)");
  check_finite_numbers(j, root);
  const std::size_t dimension = as_count(*it, root.key("dimension"), ParameterRange{2, 3, "the dimension"});
  if (dimension == 2) return parse_scene<2>(j, path);
  return parse_scene<3>(j, path);
}

AnyScene read_scene(const std::string& path) {
  reject_directory(path, "scene file");
  std::ifstream in(path);
  if (!in) throw_cannot_open(path, "cannot open the scene file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  return scene_from_json(j, path);
}

template <int D>
json to_json(const Scene<D>& scene) {
  json j;
  j["dimension"] = D;
  if (!scene.name.empty()) j["name"] = scene.name;
  if (!scene.description.empty()) j["description"] = scene.description;
  const SceneShape<D>& s = scene.shape;
  json shape;
  shape["type"] = to_string(s.type);
  if (s.type != ShapeType::file) shape["center"] = vec_json<D>(s.center);
  switch (s.type) {
    case ShapeType::circle:
    case ShapeType::sphere:
      shape["radius"] = s.radius;
      if (s.points > 0) shape["points"] = s.points;
      break;
    case ShapeType::ellipse:
      shape["semi_axes"] = vec_json<D>(s.semi_axes);
      break;
    case ShapeType::torus:
      shape["major_radius"] = s.major_radius;
      shape["minor_radius"] = s.minor_radius;
      break;
    case ShapeType::rounded_box:
      shape["half_extents"] = vec_json<D>(s.half_extents);
      shape["radius"] = s.radius;
      break;
    case ShapeType::file:
      shape["path"] = s.file;
      // Only when set aside: a scene of the file's own normals reads as it did before the key existed.
      if (s.estimate_normals) shape["normals"] = "estimated";
      break;
  }
  if (s.spacing > 0.0) shape["spacing"] = s.spacing;
  j["shape"] = shape;
  j["grid"] = scene.grid_spacing > 0.0 ? json{{"spacing", scene.grid_spacing}} : json{{"cells", scene.grid_cells}};
  j["radius_factor"] = scene.radius_factor;
  // Only when on: a scene with one Delta reads as it did before the key existed.
  if (scene.widen_support) j["widen_support"] = true;
  j["variant"] = to_string(scene.variant);
  j["deformation"] = {{"kind", to_string(scene.kind)}, {"alpha", scene.alpha}};
  // Each region once, numbered in the order the stages first use them.
  std::vector<const PointRegion<D>*> regions;
  auto region_index = [&](const PointRegion<D>* region) {
    const auto it = std::find(regions.begin(), regions.end(), region);
    if (it != regions.end()) return static_cast<std::size_t>(it - regions.begin());
    regions.push_back(region);
    return regions.size() - 1;
  };
  json stages = json::array();
  for (const HandleStage<D>& stage : scene.history.stages) {
    json targets = json::array();
    for (const HandleTarget<D>& target : stage.targets) {
      json target_json = {{"steps", target.steps}, {"handles", points_json<D>(target.handles)}};
      if (!stage.regions.empty()) {
        json motions = json::array();
        for (const RegionMotion<D>& motion : target.regions) motions.push_back(motion_json<D>(motion));
        target_json["regions"] = std::move(motions);
      }
      targets.push_back(std::move(target_json));
    }
    json stage_json = {{"handles", points_json<D>(stage.start)}, {"targets", std::move(targets)}};
    if (!stage.regions.empty()) {
      json handles = json::array();
      for (const RegionHandle<D>& handle : stage.regions) {
        json handle_json = {{"region", region_index(handle.region.get())}};
        if (handle.pinned) handle_json["pinned"] = true;
        if (!handle.motion.is_identity()) handle_json["motion"] = motion_json<D>(handle.motion);
        handles.push_back(std::move(handle_json));
      }
      stage_json["regions"] = std::move(handles);
    }
    stages.push_back(std::move(stage_json));
  }
  if (!regions.empty()) {
    json out = json::array();
    for (const PointRegion<D>* region : regions)
      out.push_back({{"points", points_json<D>(region->members())}, {"reach", region->reach()}});
    j["regions"] = std::move(out);
  }
  j["stages"] = std::move(stages);
  return j;
}

template <int D>
void write_scene(const std::string& path, const Scene<D>& scene) {
  scene.history.validate();
  write_text_file(path, to_json(scene).dump(2) + "\n");
}

template json to_json<2>(const Scene<2>&);
template json to_json<3>(const Scene<3>&);
template void write_scene<2>(const std::string&, const Scene<2>&);
template void write_scene<3>(const std::string&, const Scene<3>&);

}  // namespace amls
