#pragma once
// The renderer of a point-set surface: 3D points as lit, oriented splats, 2D points
// as dots, plus normals, the MLS curve, handles and a 2D grid. It draws into whatever
// OpenGL 3.3 core context is current (a GLFW window, or OffscreenContext) and knows
// no window system. Data are uploaded once by the set_* calls; draw() does no
// per-point work on the CPU. Every call needs the context it was made in current.
// A program that makes new point sets often (the editor) prepares them where it
// likes (prepare_points, no GL) and hands them over ready to upload.
//
//   SplatRenderer renderer;                       // after the context is current and loaded
//   renderer.set_points(points, h);               // once per new point set
//   Camera camera = Camera::orbit();
//   camera.fit(renderer.bounds(), viewport.aspect());
//   renderer.draw(camera, viewport, options);     // each frame
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "core/geometry/point_set.hpp"
#include "render/buffer_update.hpp"
#include "render/camera.hpp"
#include "render/point_data.hpp"
#include "render/render_options.hpp"

namespace amls {

// What set_points kept.
struct PointUpload {
  std::size_t drawn = 0;
  std::size_t skipped = 0;  // non-finite positions, non-finite or zero normals
  double spacing = 0.0;     // the spacing used: as given, else the median nearest-neighbour distance
};

class SplatRenderer {
 public:
  // Compiles the shaders. Throws std::runtime_error if no GL 3.3 context is current and loaded.
  explicit SplatRenderer(BufferUpdate update = BufferUpdate::best_available);
  ~SplatRenderer();
  SplatRenderer(const SplatRenderer&) = delete;
  SplatRenderer& operator=(const SplatRenderer&) = delete;

  // Replaces the points and drops the scalars. `spacing` is the sampling spacing h if
  // known (splat radius and normal length are multiples of it), else it is estimated.
  // An empty set is allowed (nothing is drawn); see prepare_points for what throws.
  PointUpload set_points(const PointSet<3>& points, std::optional<double> spacing = std::nullopt);
  PointUpload set_points(const PointSet<2>& points, std::optional<double> spacing = std::nullopt);
  // The same for points prepared already: only the GL upload is left, into the stores
  // of the last point set where it fits.
  PointUpload set_points(const PreparedPoints& points);

  // One value per point of the last set_points (skipped points included), e.g. sampling
  // quality; shown with ColorMode::scalar. NaN values get RenderOptions::missing_scalar_color.
  // Throws std::invalid_argument if the count differs.
  void set_scalars(std::span<const double> values);
  // The same, prepared already (prepare_scalars) for the last set_points.
  void set_scalars(const PreparedScalars& scalars);
  void clear_scalars();

  void set_handles(std::span<const Handle> handles);

  // The MLS curve (or any lines) as segment endpoints in pairs, world coordinates.
  void set_curve(std::span<const glm::vec3> segment_endpoints);
  void set_curve(std::span<const glm::vec2> segment_endpoints);  // z = 0

  // Draws into `viewport` of the current framebuffer. Throws std::invalid_argument for an
  // empty viewport or an unusable camera, std::runtime_error if GL reports an error.
  void draw(const Camera& camera, const Viewport& viewport, const RenderOptions& options) const;

  // Everything set so far (points widened by their spacing, curve, handles); empty if nothing.
  BoundingSphere bounds() const;
  int dimension() const { return dimension_; }  // of the last point set (3 before any)
  double spacing() const { return spacing_; }
  std::size_t point_count() const;  // drawable points
  // Whether the point buffers are persistently mapped (see StreamBuffer) or written with glBufferSubData.
  bool persistent_point_buffers() const;

 private:
  struct Passes;

  std::unique_ptr<Passes> passes_;
  int dimension_ = 3;
  double spacing_ = 1.0;
  std::size_t input_count_ = 0;
  std::vector<std::uint32_t> source_index_;  // drawable point -> input index; empty: identity
  std::optional<glm::vec2> scalar_range_;    // of the finite scalars set
  BoundingSphere point_bounds_, curve_bounds_, handle_bounds_;
};

}  // namespace amls
