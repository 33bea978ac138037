// Replacing the points of a renderer (the editor does it every step of a drag):
// new points written into the stores of the old ones, persistently mapped or
// with glBufferSubData, draw exactly what a fresh renderer given them draws.
#include <doctest/doctest.h>

#include <limits>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/util/thread_pool.hpp"
#include "render/gl.hpp"
#include "render/image.hpp"
#include "render/offscreen_context.hpp"
#include "render/point_data.hpp"
#include "render/splat_renderer.hpp"

using namespace amls;

namespace {

constexpr int kSize = 128;
const Viewport kViewport{0, 0, kSize, kSize};
constexpr BufferUpdate kUpdates[] = {BufferUpdate::best_available, BufferUpdate::sub_data};

const char* name(BufferUpdate update) { return update == BufferUpdate::sub_data ? "sub_data" : "best_available"; }

// One fixed view of the scene [-1.5, 1.5]^3, whatever the points.
Camera fixed_camera(int dimension) {
  Camera camera = dimension == 2 ? Camera::planar() : Camera::orbit();
  camera.fit(BoundingSphere{glm::vec3(0.0f), 1.5f}, 1.0f);
  return camera;
}

Image draw(const SplatRenderer& renderer, const RenderOptions& options = {}) {
  renderer.draw(fixed_camera(renderer.dimension()), kViewport, options);
  return read_framebuffer(kViewport);
}

// What a renderer made for `points` alone draws.
template <int D>
Image fresh(const PointSet<D>& points, double spacing, std::span<const double> scalars = {}) {
  SplatRenderer renderer;
  renderer.set_points(points, spacing);
  RenderOptions options;
  if (!scalars.empty()) {
    renderer.set_scalars(scalars);
    options.color_mode = ColorMode::scalar;
  }
  return draw(renderer, options);
}

// The points moved by `offset` and scaled by `scale` about the origin: as many, elsewhere.
template <int D>
PointSet<D> moved(PointSet<D> points, double offset, double scale) {
  for (Vec<D>& p : points.positions) p = scale * p + Vec<D>::Constant(offset);
  return points;
}

// `second` uploaded over `first`, either way, draws something else than `first` and what a fresh renderer draws.
template <int D>
void check_replaced(const PointSet<D>& first, const PointSet<D>& second, double spacing) {
  for (const BufferUpdate update : kUpdates) {
    CAPTURE(name(update));
    SplatRenderer renderer(update);
    renderer.set_points(first, spacing);
    const Image before = draw(renderer);
    renderer.set_points(second, spacing);
    CHECK(renderer.dimension() == D);
    const Image after = draw(renderer);
    CHECK(after != before);
    CHECK(after == fresh(second, spacing));
  }
}

}  // namespace

TEST_CASE("a changed point set of the same size, uploaded over the last, draws what a fresh renderer draws") {
  OffscreenContext context(kSize, kSize);
  check_replaced(sample_sphere(Vec<3>::Zero(), 1.0, 4000), moved(sample_sphere(Vec<3>::Zero(), 1.0, 4000), 0.3, 0.7),
                 0.05);
}

TEST_CASE("the renderer maps its point buffers persistently where the context can, and never when told not to") {
  OffscreenContext context(8, 8);
  CHECK(SplatRenderer(BufferUpdate::best_available).persistent_point_buffers() == (GLAD_GL_ARB_buffer_storage != 0));
  CHECK_FALSE(SplatRenderer(BufferUpdate::sub_data).persistent_point_buffers());
  // Mesa's llvmpipe, which the tests run on, has it: both ways are tested here.
  WARN(GLAD_GL_ARB_buffer_storage != 0);
}

TEST_CASE("a point set that grows past its store, shrinks within it, or shrinks to under half of it draws right") {
  OffscreenContext context(kSize, kSize);
  const double spacing = 0.05;
  // 4000 points, then a few more (within the eighth kept spare), many more (a new store), fewer (the same
  // store), far fewer (a new, smaller one), none, and some again.
  const std::size_t counts[] = {4000, 4300, 9000, 7000, 1000, 0, 3000};
  for (const BufferUpdate update : kUpdates) {
    CAPTURE(name(update));
    SplatRenderer renderer(update);
    for (const std::size_t count : counts) {
      CAPTURE(count);
      const PointSet<3> points = sample_sphere(Vec<3>::Zero(), 1.0, count);
      renderer.set_points(points, spacing);
      CHECK(renderer.point_count() == count);
      CHECK(draw(renderer) == fresh(points, spacing));
    }
  }
}

TEST_CASE("scalars uploaded over the last ones colour the new points as a fresh renderer does") {
  OffscreenContext context(kSize, kSize);
  const double spacing = 0.05;
  const PointSet<3> points = sample_sphere(Vec<3>::Zero(), 1.0, 4000);
  std::vector<double> low(points.size()), high(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    low[i] = points.positions[i].x();
    high[i] = points.positions[i].y();
  }
  RenderOptions options;
  options.color_mode = ColorMode::scalar;
  for (const BufferUpdate update : kUpdates) {
    CAPTURE(name(update));
    SplatRenderer renderer(update);
    renderer.set_points(points, spacing);
    renderer.set_scalars(low);
    const Image before = draw(renderer, options);
    renderer.set_points(moved(points, 0.1, 1.0), spacing);
    renderer.set_scalars(high);
    const Image after = draw(renderer, options);
    CHECK(after != before);
    CHECK(after == fresh(moved(points, 0.1, 1.0), spacing, high));
  }
}

TEST_CASE("a 2D point set uploaded over the last draws its dots where a fresh renderer does") {
  OffscreenContext context(kSize, kSize);
  check_replaced(sample_circle(Vec<2>::Zero(), 1.0, 200), moved(sample_circle(Vec<2>::Zero(), 1.0, 200), -0.2, 0.8),
                 0.03);
}

TEST_CASE("points prepared on a thread pool are those prepared alone, undrawable ones left out alike") {
  PointSet<3> points = sample_sphere(Vec<3>::Zero(), 1.0, 5000);
  points.positions[7] = Vec<3>::Constant(std::numeric_limits<double>::quiet_NaN());
  points.normals[4000] = Vec<3>::Zero();
  points.positions[4999].x() = 1e300;  // finite as a double, not as a float
  const PreparedPoints alone = prepare_points<3>(points, std::nullopt);
  ThreadPool pool(3);
  const PreparedPoints pooled = prepare_points<3>(points, std::nullopt, &pool);
  CHECK(alone.skipped == 3);
  CHECK(pooled.skipped == 3);
  CHECK(pooled.positions == alone.positions);
  CHECK(pooled.normals == alone.normals);
  CHECK(pooled.source_index == alone.source_index);
  CHECK(pooled.source_index.size() == points.size() - 3);
  CHECK(pooled.spacing == alone.spacing);
  CHECK(pooled.bounds.center == alone.bounds.center);
  CHECK(pooled.bounds.radius == alone.bounds.radius);
  const BoundingSphere around = bounding_sphere(alone.positions);  // widened by the spacing
  CHECK(alone.bounds.center == around.center);
  CHECK(alone.bounds.radius == around.radius + static_cast<float>(alone.spacing));
}
