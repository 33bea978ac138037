// The editor's selections on screen: the lasso and the brush (app/editor/lasso.hpp,
// app/editor/brush_stroke.hpp), on a unit sphere seen from +z.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "app/editor/brush_stroke.hpp"
#include "app/editor/lasso.hpp"
#include "view_fixtures.hpp"

using namespace amls;
using namespace amls::editor;
using namespace amls::test;

namespace {

// A Fibonacci sphere of radius 1 with outward normals.
std::shared_ptr<const PreparedPoints> sphere_points(std::size_t count) {
  auto points = std::make_shared<PreparedPoints>();
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(count);
    const double r = std::sqrt(1.0 - z * z), a = golden * static_cast<double>(i);
    const glm::vec3 p(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), static_cast<float>(z));
    points->positions.push_back(p);
    points->normals.push_back(p);
  }
  points->input_count = count;
  return points;
}

}  // namespace

TEST_CASE("selection: a lasso around the whole sphere takes its front and nothing of its back") {
  const auto points = sphere_points(2000);
  const Camera camera = orbit_camera();
  const std::vector<glm::vec2> square{{0, 0}, {800, 0}, {800, 600}, {0, 600}};
  const std::vector<std::size_t> ids = lasso_select(points->positions, points->normals, camera, kViewport, square);
  std::size_t facing = 0;
  for (std::size_t i = 0; i < points->size(); ++i)
    facing += glm::dot(points->normals[i], camera.eye() - points->positions[i]) > 0.0f ? 1 : 0;
  CHECK(ids.size() == facing);
  for (const std::size_t i : ids) CHECK(points->positions[i].z > 0.0f);
}

TEST_CASE("selection: a brush stroke paints a sphere about the points under the cursor, front only") {
  const auto points = sphere_points(4000);
  const Camera camera = orbit_camera();
  const float radius = 0.3f;
  BrushStroke stroke(points, radius);
  REQUIRE(stroke.paint(camera, kViewport, window_of(camera, {0.0f, 0.0f, 1.0f}), 12.0f));
  const std::size_t first = stroke.painted().size();
  CHECK(first > 50);
  for (const std::size_t i : stroke.painted()) CHECK(glm::distance(points->positions[i], stroke.centres()[0]) <= radius);
  // A stroke to the right adds the points about its new place, each once.
  const glm::vec3 right(std::sin(0.4f), 0.0f, std::cos(0.4f));
  REQUIRE(stroke.paint(camera, kViewport, window_of(camera, right), 12.0f));
  CHECK(stroke.painted().size() > first);
  std::vector<int> seen(points->size(), 0);
  for (const std::size_t i : stroke.painted()) CHECK(++seen[i] == 1);
  CHECK(stroke.covers(right));
  CHECK_FALSE(stroke.covers({0.0f, 0.0f, -1.0f}));
  // Off the sphere there is nothing to paint.
  CHECK_FALSE(stroke.paint(camera, kViewport, {2.0f, 2.0f}, 12.0f));
}

TEST_CASE("selection: a brush wider than the sphere does not reach through to its back") {
  const auto points = sphere_points(2000);
  const Camera camera = orbit_camera();
  BrushStroke stroke(points, 3.0f);
  REQUIRE(stroke.paint(camera, kViewport, window_of(camera, {0.0f, 0.0f, 1.0f}), 12.0f));
  CHECK(stroke.painted().size() > 500);
  for (const std::size_t i : stroke.painted())
    CHECK(glm::dot(points->normals[i], camera.eye() - points->positions[i]) > 0.0f);
}

TEST_CASE("selection: a brush needs points and a radius > 0") {
  CHECK_THROWS_AS(BrushStroke(sphere_points(10), 0.0f), std::invalid_argument);
  CHECK_THROWS_AS(BrushStroke(sphere_points(10), std::nanf("")), std::invalid_argument);
  CHECK_THROWS_AS(BrushStroke(std::make_shared<PreparedPoints>(), 1.0f), std::invalid_argument);
}
