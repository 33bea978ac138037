#include "render/picture.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/io/point_set_io.hpp"
#include "core/surface/spacing_band.hpp"
#include "render/point_data.hpp"

namespace amls {

namespace {

// 2D dots: about this fraction of the spacing on screen, within these pixel sizes, in a
// colour that stands apart from the curve's yellow; the curve a little wider than a pixel.
constexpr float kDotFractionOfSpacing = 0.45f, kDotMinPx = 1.5f, kDotMaxPx = 7.0f;
constexpr glm::vec3 kDotColor{0.45f, 0.80f, 0.95f};
constexpr float kCurveWidthPx = 2.0f;
// Handles in a picture mark places; smaller than the editor's, which are grabbed.
constexpr float kHandleSizePx = 10.0f;
// Framed pictures leave this fraction of the half size free around the shape.
constexpr float kFrameMargin = 1.06f;

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

RenderJob picture_job(const Picture& picture, ImageSize size, const std::optional<OrbitView>& view,
                      RenderOptions options) {
  if (picture.dimension == 2 && view)
    throw std::invalid_argument("an orbit view is for 3D pictures; a 2D one is always seen from above, framed to fit");
  if (picture.points.empty()) throw std::invalid_argument("nothing to draw: the picture has no points");
  RenderJob job;
  job.width = size.width;
  job.height = size.height;
  job.framing = Framing::keep;
  if (options.color_mode == ColorMode::scalar) options.scalar_range = glm::vec2(kSpacingBandLow, kSpacingBandHigh);
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
