#include "render/splat_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "render/frame.hpp"
#include "render/gl_check.hpp"
#include "render/grid_pass.hpp"
#include "render/handle_pass.hpp"
#include "render/line_pass.hpp"
#include "render/point_buffers.hpp"
#include "render/point_data.hpp"
#include "render/point_pass.hpp"
#include "render/splat_pass.hpp"

namespace amls {

struct SplatRenderer::Passes {
  explicit Passes(BufferUpdate update) : points(update) {}

  PointBuffers points;
  SplatPass splats;
  PointPass dots;
  LinePass lines;
  HandlePass handles;
  GridPass grid;
};

namespace {

// The near-plane distance of a glm::perspective matrix: P[3][2] / (P[2][2] - 1).
float near_plane_of(const glm::mat4& projection) { return projection[3][2] / (projection[2][2] - 1.0f); }

}  // namespace

SplatRenderer::SplatRenderer(BufferUpdate update) {
  require_gl_context("SplatRenderer");
  passes_ = std::make_unique<Passes>(update);
  check_gl("compiling the renderer's shaders");
}

SplatRenderer::~SplatRenderer() = default;

PointUpload SplatRenderer::set_points(const PreparedPoints& points) {
  passes_->points.upload(points);
  dimension_ = points.dimension;
  spacing_ = points.spacing;
  input_count_ = points.input_count;
  source_index_ = points.source_index;
  scalar_range_.reset();
  point_bounds_ = points.bounds;
  return {points.size(), points.skipped, points.spacing};
}

PointUpload SplatRenderer::set_points(const PointSet<3>& points, std::optional<double> spacing) {
  return set_points(prepare_points<3>(points, spacing));
}

PointUpload SplatRenderer::set_points(const PointSet<2>& points, std::optional<double> spacing) {
  return set_points(prepare_points<2>(points, spacing));
}

void SplatRenderer::set_scalars(std::span<const double> values) {
  set_scalars(prepare_scalars(values, input_count_, source_index_));
}

void SplatRenderer::set_scalars(const PreparedScalars& scalars) {
  passes_->points.upload_scalars(scalars.values);
  scalar_range_ = scalars.range;
}

void SplatRenderer::clear_scalars() {
  passes_->points.drop_scalars();
  scalar_range_.reset();
}

void SplatRenderer::set_handles(std::span<const Handle> handles) {
  passes_->handles.set_handles(handles);
  std::vector<glm::vec3> positions;
  positions.reserve(handles.size());
  for (const Handle& h : handles) positions.push_back(h.position);
  handle_bounds_ = bounding_sphere(positions);
}

void SplatRenderer::set_curve(std::span<const glm::vec3> segment_endpoints) {
  passes_->lines.set_segments(segment_endpoints);
  curve_bounds_ = bounding_sphere(segment_endpoints);
}

void SplatRenderer::set_curve(std::span<const glm::vec2> segment_endpoints) {
  std::vector<glm::vec3> lifted;
  lifted.reserve(segment_endpoints.size());
  for (const glm::vec2& p : segment_endpoints) lifted.emplace_back(p, 0.0f);
  set_curve(std::span<const glm::vec3>(lifted));
}

BoundingSphere SplatRenderer::bounds() const { return merge(merge(point_bounds_, curve_bounds_), handle_bounds_); }

std::size_t SplatRenderer::point_count() const { return passes_->points.count(); }

bool SplatRenderer::persistent_point_buffers() const { return passes_->points.persistent(); }

void SplatRenderer::draw(const Camera& camera, const Viewport& viewport, const RenderOptions& options) const {
  if (viewport.width <= 0 || viewport.height <= 0)
    throw std::invalid_argument("cannot draw into an empty viewport (" + std::to_string(viewport.width) + "x" +
                                std::to_string(viewport.height) + ")");
  camera.validate();
  validate(options);

  // Near and far planes must hold everything drawn, whatever scene the camera was fitted to:
  // splats and normals reach beyond the points (and splat.vert drops a splat that may
  // cross the near plane, so a scene too small would cut holes in the front).
  BoundingSphere drawn = bounds();
  if (!point_bounds_.empty()) {
    const float reach = std::max(options.splat_scale, options.show_normals ? options.normal_length : 0.0f);
    drawn = merge(drawn, {point_bounds_.center, point_bounds_.radius + reach * static_cast<float>(spacing_)});
  }
  Camera view_camera = camera;
  view_camera.scene = merge(camera.scene, drawn);
  Frame frame{options, viewport};
  frame.mode = camera.mode;
  frame.view = view_camera.view();
  frame.projection = view_camera.projection(viewport.aspect());
  frame.view_projection = frame.projection * frame.view;
  frame.near_plane = frame.perspective() ? near_plane_of(frame.projection) : 0.0f;
  frame.spacing = static_cast<float>(spacing_);
  const bool scalars = options.color_mode == ColorMode::scalar && passes_->points.has_scalars();
  frame.color_mode = scalars || options.color_mode != ColorMode::scalar ? options.color_mode : ColorMode::uniform;
  frame.scalar_range = options.scalar_range.value_or(scalar_range_.value_or(glm::vec2(0.0f, 1.0f)));

  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  if (options.clear) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(viewport.x, viewport.y, viewport.width, viewport.height);
    glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glEnable(GL_PROGRAM_POINT_SIZE);  // core profile: gl_PointSize is ignored without it

  Passes& p = *passes_;
  glDisable(GL_DEPTH_TEST);
  if (options.show_grid) p.grid.draw(frame, options.grid_spacing > 0.0f ? options.grid_spacing : frame.spacing);
  if (dimension_ == 2) {
    // A flat picture, painted back to front: normals, curve, then the points on top of both.
    if (options.show_normals) p.lines.draw_normals(p.points, frame);
    if (options.show_curve) p.lines.draw_segments(frame);
    if (options.show_points) p.dots.draw(p.points, frame);
  } else {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    if (options.show_points) p.splats.draw(p.points, frame);
    if (options.show_normals) p.lines.draw_normals(p.points, frame);
    if (options.show_curve) p.lines.draw_segments(frame);
    glDisable(GL_DEPTH_TEST);
  }
  if (options.show_handles) p.handles.draw(frame);  // always on top

  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("drawing the point set");
}

}  // namespace amls
