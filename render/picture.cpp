#include "render/picture.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <variant>

#include "core/surface/curve_tracing.hpp"
#include "core/io/mesh_io.hpp"
#include "core/surface/metrics.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/scene_state.hpp"
#include "core/io/surface_samples.hpp"
#include "render/point_data.hpp"

namespace amls {

namespace {

// Meshes without a given spacing are sampled at their bounding box's diagonal over this.
constexpr double kMeshSamplesPerDiagonal = 200.0;
// The quality colour range in units of h: resampling keeps the spacing within these bounds.
constexpr float kQualityLow = 0.3f, kQualityHigh = 1.5f;
// 2D dots: about this fraction of the spacing on screen, within these pixel sizes, in a
// colour that stands apart from the curve's yellow; the curve a little wider than a pixel.
constexpr float kDotFractionOfSpacing = 0.45f, kDotMinPx = 1.5f, kDotMaxPx = 7.0f;
constexpr glm::vec3 kDotColor{0.45f, 0.80f, 0.95f};
constexpr float kCurveWidthPx = 2.0f;
// Handles in a picture mark places; smaller than the editor's, which are grabbed.
constexpr float kHandleSizePx = 10.0f;
// Framed pictures leave this fraction of the half size free around the shape.
constexpr float kFrameMargin = 1.06f;

std::string lowercase_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Every point drawable: the renderer would skip the others silently, but a file with
// a broken point is an error worth telling.
void require_drawable(const PointSet<3>& points, const std::string& path) {
  if (points.empty()) throw std::runtime_error(path + ": holds no points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec<3>& p = points.positions[i];
    const Vec<3>& n = points.normals[i];
    if (!p.allFinite())
      throw std::runtime_error(path + ": point " + std::to_string(i) + " has a non-finite position (" +
                               format_number(p[0]) + ", " + format_number(p[1]) + ", " + format_number(p[2]) + ")");
    if (!n.allFinite() || n.squaredNorm() == 0.0)
      throw std::runtime_error(path + ": point " + std::to_string(i) + " has " +
                               (n.allFinite() ? "a zero normal" : "a non-finite normal") + " (" + format_number(n[0]) +
                               ", " + format_number(n[1]) + ", " + format_number(n[2]) + ")");
  }
}

// The MLS curve of a 2D point set: its AMLS surface on `grid`, traced.
std::vector<glm::vec2> mls_curve(const PointSet<2>& points, const Grid<2>& grid, const AmlsParameters& parameters,
                                 int threads) {
  ThreadPool pool(threads);
  AmlsSurface<2> surface(grid, parameters);
  surface.set_points(points);
  surface.hash_points();
  surface.update_normals(pool);
  std::vector<glm::vec2> out;
  const TracedCurve curve = trace_curve(surface, pool);
  out.reserve(2 * curve.segments.size());
  for (const CurveSegment& s : curve.segments) {
    out.emplace_back(static_cast<float>(s.a[0]), static_cast<float>(s.a[1]));
    out.emplace_back(static_cast<float>(s.b[0]), static_cast<float>(s.b[1]));
  }
  return out;
}

void add_quality(Picture& picture) {
  picture.quality = picture.dimension == 2 ? nearest_neighbour_spacing_per_point(to_2d(picture.points), picture.h)
                                           : nearest_neighbour_spacing_per_point(picture.points, picture.h);
  if (picture.quality.empty()) picture.quality.assign(picture.points.size(), std::nan(""));  // a single point
}

template <int D>
Picture scene_picture(const Scene<D>& scene, const PictureInputOptions& options) {
  const std::size_t total = scene.history.total_steps();
  const std::size_t step = options.step.value_or(0) == kFinalStep ? total : options.step.value_or(0);
  if (step > total)
    throw std::invalid_argument(scene.path + ": --step " + std::to_string(step) + " is past the scene's end: it has " +
                                std::to_string(total) + " steps (--step last draws its final state)");
  SceneState<D> state = scene_state_after(scene, step, options.threads, options.progress);
  Picture picture;
  picture.dimension = D;
  picture.h = state.grid.spacing();
  picture.warnings = std::move(state.warnings);
  if constexpr (D == 2) {
    if (options.curve) picture.curve = mls_curve(state.points, state.grid, state.parameters, options.threads);
  }
  for (const Vec<D>& handle : state.handles) picture.handles.push_back(to_vec3<D>(handle));
  if constexpr (D == 2)
    picture.points = to_3d(state.points);
  else
    picture.points = std::move(state.points);
  picture.description = "scene " + (scene.name.empty() ? scene.path : scene.name) + " (" + std::to_string(D) +
                        "D) after " + std::to_string(step) + " of " + std::to_string(total) +
                        " steps: " + std::to_string(picture.points.size()) + " points, h = " + format_number(picture.h);
  return picture;
}

Picture file_picture(const std::string& path, const PictureInputOptions& options) {
  if (options.spacing != 0.0) check_range("--spacing", options.spacing, ranges::kSpacing);
  Picture picture;
  SurfaceSampleOptions sampling;
  sampling.dimension = options.dimension;
  sampling.threads = options.threads;
  SurfaceSamples samples;
  if (is_mesh_file(path)) {
    double h = options.spacing;
    if (h == 0.0) {
      const TriangleMesh mesh = read_mesh(path);
      Vec<3> lo = Vec<3>::Constant(INFINITY), hi = Vec<3>::Constant(-INFINITY);
      for (const Vec<3>& v : mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      const double diagonal = mesh.vertices.empty() ? 0.0 : (hi - lo).norm();
      if (!(diagonal > 0.0) || !std::isfinite(diagonal))
        throw std::runtime_error(path + ": the mesh has no extent to sample (give --spacing)");
      h = diagonal / kMeshSamplesPerDiagonal;
    }
    sampling.spacing = h;
    samples = load_surface_samples(path, sampling);
    picture.h = h;
  } else {
    LoadedPointSet loaded = read_point_set(path, options.dimension);
    if (loaded.points.empty()) throw std::runtime_error(path + ": holds no points");
    // Positions first: the spacing estimate and the normal estimation need them finite.
    for (std::size_t i = 0; i < loaded.points.size(); ++i)
      if (!loaded.points.positions[i].allFinite())
        throw std::runtime_error(path + ": point " + std::to_string(i) + " has a non-finite position");
    double h = options.spacing;
    if (h == 0.0) {
      h = estimate_spacing<3>(loaded.points.positions);
      if (!(h > 0.0))
        throw std::runtime_error(path + ": fewer than two distinct points, so no spacing to estimate; give --spacing");
    }
    picture.h = h;
    if (loaded.has_normals) {
      samples.dimension = loaded.dimension;
      samples.points = std::move(loaded.points);
      samples.source = "point set of " + std::to_string(samples.points.size()) + " points with normals";
      samples.warnings = std::move(loaded.warnings);
    } else {
      sampling.dimension = loaded.dimension;
      sampling.normal_radius = options.radius_factor * h;
      samples = load_surface_samples(path, sampling);  // reads it again, estimating normals over Delta
    }
  }
  require_drawable(samples.points, path);
  picture.dimension = samples.dimension;
  picture.points = std::move(samples.points);
  picture.warnings = std::move(samples.warnings);
  picture.description = path + ": " + samples.source + " (" + std::to_string(picture.dimension) +
                        "D), h = " + format_number(picture.h) + (options.spacing > 0.0 ? "" : " (estimated)");
  if (options.curve && picture.dimension == 2) {
    const PointSet<2> flat = to_2d(picture.points);
    PointSetResampling grid_options;
    grid_options.spacing = picture.h;
    grid_options.radius_factor = options.radius_factor;
    picture.curve =
        mls_curve(flat, resampling_grid(flat, grid_options), AmlsParameters{options.radius_factor}, options.threads);
  }
  return picture;
}

float parse_float(const std::string& text, const std::string& what) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw std::invalid_argument(what + ": '" + text + "' is not a number");
  if (!std::isfinite(value)) throw std::invalid_argument(what + ": " + text + " is not finite");
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find(separator, begin);
    parts.push_back(text.substr(begin, end == std::string::npos ? std::string::npos : end - begin));
    if (end == std::string::npos) return parts;
    begin = end + 1;
  }
}

// The box around everything drawn, in the camera's axes (right, up, towards the eye).
struct ViewBox {
  glm::vec3 center{0.0f};  // world coordinates
  glm::vec3 half{0.0f};    // half sizes along right, up, towards the eye
  BoundingSphere sphere;   // around the box
};

// Everything drawn (points, curve, handles) seen along the camera's direction, with
// `overhang` added around the points. Pictures are framed on this box rather than on a
// bounding sphere: an elongated shape then fills the image.
ViewBox view_box(const Picture& picture, const Camera& camera, float overhang) {
  Camera axes = camera;
  axes.target = glm::vec3(0.0f);
  const glm::mat4 v = axes.view();
  const glm::vec3 right{v[0][0], v[1][0], v[2][0]}, up{v[0][1], v[1][1], v[2][1]}, back{v[0][2], v[1][2], v[2][2]};
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  auto add = [&](const glm::vec3& p, float pad) {
    const glm::vec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, back));
    lo = glm::min(lo, q - pad);
    hi = glm::max(hi, q + pad);
  };
  for (const Vec<3>& p : picture.points.positions) add(to_vec3<3>(p), overhang);
  for (const glm::vec2& c : picture.curve) add(glm::vec3(c, 0.0f), 0.0f);
  for (const glm::vec3& handle : picture.handles) add(handle, 0.0f);
  ViewBox box;
  const glm::vec3 mid = 0.5f * (lo + hi);
  box.center = mid.x * right + mid.y * up + mid.z * back;
  box.half = glm::max(0.5f * (hi - lo), glm::vec3(1e-6f));
  box.sphere = {box.center, glm::length(box.half)};
  return box;
}

// Places a perspective camera (direction kept) so that everything drawn just fits: each
// point, widened by `overhang`, within the field of view less the margin, and the
// projected extent centred. Two rounds, since centring moves the points in depth a little.
void fit_perspective(Camera& camera, const Picture& picture, float overhang, float aspect) {
  const float tan_y = std::tan(0.5f * glm::radians(camera.fov_y_deg)) / kFrameMargin;
  const float tan_x = tan_y * aspect;
  std::vector<glm::vec3> drawn;
  drawn.reserve(picture.points.size() + picture.handles.size());
  for (const Vec<3>& p : picture.points.positions) drawn.push_back(to_vec3<3>(p));
  drawn.insert(drawn.end(), picture.handles.begin(), picture.handles.end());
  for (int round = 0; round < 3; ++round) {
    const glm::mat4 v = camera.view();
    const glm::vec3 right{v[0][0], v[1][0], v[2][0]}, up{v[0][1], v[1][1], v[2][1]}, back{v[0][2], v[1][2], v[2][2]};
    // A point at (x, y, z) in the camera's axes about the target is d - z from the eye, so
    // it fits when d >= z + |x| / tan_x and d >= z + |y| / tan_y.
    float distance = 0.0f;
    for (const glm::vec3& p : drawn) {
      const glm::vec3 d = p - camera.target;
      const float x = std::abs(glm::dot(d, right)) + overhang, y = std::abs(glm::dot(d, up)) + overhang;
      const float z = glm::dot(d, back) + overhang;
      distance = std::max({distance, z + x / tan_x, z + y / tan_y});
    }
    camera.distance = distance;
    if (round == 2) return;
    // Centre the projection: shift the target by the middle of the projected extent.
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : drawn) {
      const glm::vec3 d = p - camera.target;
      const float depth = distance - glm::dot(d, back);
      const glm::vec2 projected(glm::dot(d, right) / depth, glm::dot(d, up) / depth);
      lo = glm::min(lo, projected);
      hi = glm::max(hi, projected);
    }
    const glm::vec2 middle = 0.5f * (lo + hi) * distance;
    camera.target += middle.x * right + middle.y * up;
  }
}

}  // namespace

void Picture::fill(SplatRenderer& renderer) const {
  const PointUpload upload = dimension == 2 ? renderer.set_points(to_2d(points), h) : renderer.set_points(points, h);
  if (upload.drawn == 0) throw std::invalid_argument("nothing to draw: no point has a finite position and normal");
  if (!quality.empty()) renderer.set_scalars(quality);
  if (!curve.empty()) renderer.set_curve(curve);
  std::vector<Handle> drawn;
  for (const glm::vec3& position : handles) drawn.push_back({position, HandleState::idle});
  renderer.set_handles(drawn);
}

Picture load_picture(const std::string& path, const PictureInputOptions& options) {
  check_range("--radius-factor", options.radius_factor, ranges::kRadiusFactor);
  Picture picture;
  if (lowercase_extension(path) == ".json") {
    if (options.spacing != 0.0)
      throw std::invalid_argument(path +
                                  ": a scene has its own grid; --spacing and --grid are for point sets and meshes");
    if (options.dimension != 0)
      throw std::invalid_argument(path + ": a scene has its own dimension; --dim is for point sets");
    const AnyScene scene = read_scene(path);
    picture = std::visit([&](const auto& s) { return scene_picture(s, options); }, scene);
  } else {
    if (options.step)
      throw std::invalid_argument(path + ": --step is for scenes (.json), not for point sets or meshes");
    picture = file_picture(path, options);
  }
  if (options.quality) add_quality(picture);
  return picture;
}

OrbitView parse_view(const std::string& text) {
  const std::vector<std::string> parts = split(text, ',');
  if (parts.size() != 2 && parts.size() != 3)
    throw std::invalid_argument(
        "--view must be 'azimuth,elevation' or 'azimuth,elevation,distance' (degrees, "
        "degrees, world units), got '" +
        text + "'");
  OrbitView view;
  view.azimuth_deg = parse_float(parts[0], "--view azimuth");
  view.elevation_deg = parse_float(parts[1], "--view elevation");
  if (std::abs(view.elevation_deg) > 89.9f)
    throw std::invalid_argument("--view elevation must be within [-89.9, 89.9] degrees, got " + parts[1]);
  if (parts.size() == 3) {
    view.distance = parse_float(parts[2], "--view distance");
    if (!(*view.distance > 0.0f)) throw std::invalid_argument("--view distance must be above 0, got " + parts[2]);
  }
  return view;
}

RenderJob picture_job(const Picture& picture, ImageSize size, const std::optional<OrbitView>& view,
                      RenderOptions options) {
  if (picture.dimension == 2 && view)
    throw std::invalid_argument("--view is for 3D inputs; a 2D input is always seen from above, framed to fit");
  if (picture.points.empty()) throw std::invalid_argument("nothing to draw: the picture has no points");
  RenderJob job;
  job.width = size.width;
  job.height = size.height;
  job.framing = Framing::keep;
  if (options.color_mode == ColorMode::scalar) options.scalar_range = glm::vec2(kQualityLow, kQualityHigh);
  options.handle_size_px = kHandleSizePx;
  const float aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  const float h = static_cast<float>(picture.h);

  if (picture.dimension == 2) {
    Camera camera = Camera::planar();
    const ViewBox box = view_box(picture, camera, h);
    camera.target = box.center;
    camera.half_height = kFrameMargin * std::max(box.half.y, box.half.x / aspect);
    camera.scene = box.sphere;
    const float spacing_px = h * static_cast<float>(size.height) / (2.0f * camera.half_height);
    options.point_size_px = std::clamp(kDotFractionOfSpacing * spacing_px, kDotMinPx, kDotMaxPx);
    options.surface_color = kDotColor;
    options.line_width_px = kCurveWidthPx;
    job.camera = camera;
    job.options = options;
    return job;
  }

  const OrbitView v = view.value_or(OrbitView{});
  Camera camera = Camera::orbit();
  camera.azimuth_deg = v.azimuth_deg;
  camera.elevation_deg = v.elevation_deg;
  // What sticks out of the points: splats, and normals if drawn.
  const float overhang = h * std::max(options.splat_scale, options.show_normals ? options.normal_length : 0.0f);
  const ViewBox box = view_box(picture, camera, overhang);
  camera.target = box.center;
  camera.scene = box.sphere;
  if (v.distance)
    camera.distance = *v.distance;
  else
    fit_perspective(camera, picture, overhang, aspect);
  job.camera = camera;
  job.options = options;
  return job;
}

}  // namespace amls
