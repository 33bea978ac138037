// The editor's selections on screen: the lasso and the brush (app/editor/lasso.hpp,
// app/editor/brush_stroke.hpp) and the screen grid the brush finds its points
// in (app/editor/screen_grid.hpp), on a unit sphere seen from +z.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "app/editor/brush_stroke.hpp"
#include "app/editor/lasso.hpp"
#include "app/editor/picking.hpp"
#include "app/editor/screen_grid.hpp"
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
  const std::vector<std::size_t> ids = lasso_select(ScreenGrid(points->positions, camera, kViewport, 4.0f),
                                                    points->positions, points->normals, camera, square);
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
  const ScreenGrid grid(points->positions, camera, kViewport, 4.0f);
  BrushStroke stroke(points, radius);
  REQUIRE(stroke.paint(grid, camera, window_of(camera, {0.0f, 0.0f, 1.0f}), 12.0f));
  const std::size_t first = stroke.painted().size();
  CHECK(first > 50);
  for (const std::size_t i : stroke.painted()) CHECK(glm::distance(points->positions[i], stroke.centres()[0]) <= radius);
  // A stroke to the right adds the points about its new place, each once.
  const glm::vec3 right(std::sin(0.4f), 0.0f, std::cos(0.4f));
  REQUIRE(stroke.paint(grid, camera, window_of(camera, right), 12.0f));
  CHECK(stroke.painted().size() > first);
  std::vector<int> seen(points->size(), 0);
  for (const std::size_t i : stroke.painted()) CHECK(++seen[i] == 1);
  CHECK(stroke.covers(right));
  CHECK_FALSE(stroke.covers({0.0f, 0.0f, -1.0f}));
  // Off the sphere there is nothing to paint.
  CHECK_FALSE(stroke.paint(grid, camera, {2.0f, 2.0f}, 12.0f));
  // A grid of other points is refused.
  const auto fewer = sphere_points(100);
  CHECK_THROWS_AS(stroke.paint(ScreenGrid(fewer->positions, camera, kViewport, 4.0f), camera, {400.0f, 300.0f}, 12.0f),
                  std::invalid_argument);
}

TEST_CASE("selection: a brush wider than the sphere does not reach through to its back") {
  const auto points = sphere_points(2000);
  const Camera camera = orbit_camera();
  BrushStroke stroke(points, 3.0f);
  REQUIRE(stroke.paint(ScreenGrid(points->positions, camera, kViewport, 4.0f), camera,
                       window_of(camera, {0.0f, 0.0f, 1.0f}), 12.0f));
  CHECK(stroke.painted().size() > 500);
  for (const std::size_t i : stroke.painted())
    CHECK(glm::dot(points->normals[i], camera.eye() - points->positions[i]) > 0.0f);
}

TEST_CASE("selection: a brush needs points and a radius > 0") {
  CHECK_THROWS_AS(BrushStroke(sphere_points(10), 0.0f), std::invalid_argument);
  CHECK_THROWS_AS(BrushStroke(sphere_points(10), std::nanf("")), std::invalid_argument);
  CHECK_THROWS_AS(BrushStroke(std::make_shared<PreparedPoints>(), 1.0f), std::invalid_argument);
}

TEST_CASE("selection: the lasso's polygon test follows the even-odd rule, concave corners included") {
  // An L: the square [0, 20]^2 without its upper right quarter [10, 20]^2.
  const std::vector<glm::vec2> ell{{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
  CHECK(inside_polygon(ell, {5, 5}));
  CHECK(inside_polygon(ell, {15, 5}));
  CHECK(inside_polygon(ell, {5, 15}));
  CHECK_FALSE(inside_polygon(ell, {15, 15}));  // the notch
  CHECK_FALSE(inside_polygon(ell, {-1, 5}));
  CHECK_FALSE(inside_polygon(ell, {25, 5}));
  // A bow tie crossing itself: its two lobes are inside, the region outside both is not.
  const std::vector<glm::vec2> bow{{0, 0}, {20, 20}, {20, 0}, {0, 20}};
  CHECK(inside_polygon(bow, {3, 10}));
  CHECK(inside_polygon(bow, {17, 10}));
  CHECK_FALSE(inside_polygon(bow, {10, 3}));
}

TEST_CASE("selection: a lasso in the planar view takes the points inside it, whichever way they face") {
  std::vector<glm::vec3> positions, normals;
  for (int i = -5; i <= 5; ++i) {
    positions.emplace_back(0.1f * static_cast<float>(i), 0.0f, 0.0f);
    normals.emplace_back(0.0f, 0.0f, i % 2 == 0 ? 1.0f : -1.0f);
  }
  const Camera camera = planar_camera();
  const glm::vec2 a = window_of(camera, {-0.25f, -0.1f, 0.0f}), b = window_of(camera, {0.25f, 0.1f, 0.0f});
  const std::vector<glm::vec2> box{{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}};
  // x = -0.2 ... 0.2: points 3 to 7.
  CHECK(lasso_select(ScreenGrid(positions, camera, kViewport, 4.0f), positions, normals, camera, box) ==
        std::vector<std::size_t>{3, 4, 5, 6, 7});
}

namespace {

// What brush_select must find: every point within the radius that faces the eye, by looking at all of them.
std::vector<std::size_t> brush_by_hand(const PreparedPoints& points, const Camera& camera, const glm::vec3& centre,
                                       float radius) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (glm::distance(points.positions[i], centre) <= radius &&
        glm::dot(points.normals[i], camera.eye() - points.positions[i]) > 0.0f)
      out.push_back(i);
  return out;
}

}  // namespace

TEST_CASE("selection: the brush finds in the screen grid what a look at every point finds, off screen too") {
  const auto points = sphere_points(6000);
  Camera wide = orbit_camera(30.0f);
  // Zoomed in so far that most of the sphere lies off screen, and the eye inside the sphere's bounding box.
  Camera near = orbit_camera(-20.0f);
  near.distance = 1.3f;
  for (const Camera& camera : {orbit_camera(), wide, near}) {
    const ScreenGrid grid(points->positions, camera, kViewport, 5.0f);
    for (const glm::vec3 centre : {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.6f, 0.0f, 0.8f),
                                   glm::vec3(0.0f, -1.0f, 0.0f), glm::normalize(glm::vec3(-0.7f, 0.5f, 0.5f))})
      for (const float radius : {0.05f, 0.3f, 1.2f}) {
        CAPTURE(centre.x);
        CAPTURE(radius);
        CHECK(brush_select(grid, points->positions, points->normals, camera, centre, radius) ==
              brush_by_hand(*points, camera, centre, radius));
      }
  }
}

TEST_CASE("selection: the lasso finds in the screen grid what a look at every point finds, past the view's edge too") {
  const auto points = sphere_points(6000);
  Camera near = orbit_camera(25.0f);
  near.distance = 2.0f;  // the sphere reaches past the view on every side
  // A star about the view's centre whose points reach far past its edges, and a small triangle.
  std::vector<glm::vec2> star;
  for (int k = 0; k < 10; ++k) {
    const float a = 0.2f * std::numbers::pi_v<float> * static_cast<float>(k), r = k % 2 == 0 ? 900.0f : 150.0f;
    star.emplace_back(400.0f + r * std::cos(a), 300.0f + r * std::sin(a));
  }
  const std::vector<glm::vec2> triangle{{380, 280}, {460, 300}, {400, 350}};
  for (const Camera& camera : {orbit_camera(), near})
    for (const std::vector<glm::vec2>& polygon : {star, triangle}) {
      std::vector<std::size_t> by_hand;
      for (std::size_t i = 0; i < points->size(); ++i) {
        const glm::vec3 w = camera.to_window(points->positions[i], kViewport);
        if (w.z >= 0.0f && w.z <= 1.0f && inside_polygon(polygon, glm::vec2(w)) &&
            glm::dot(points->normals[i], camera.eye() - points->positions[i]) > 0.0f)
          by_hand.push_back(i);
      }
      CHECK_FALSE(by_hand.empty());
      CHECK(lasso_select(ScreenGrid(points->positions, camera, kViewport, 5.0f), points->positions, points->normals,
                         camera, polygon) == by_hand);
    }
}

TEST_CASE("selection: the pick in the screen grid is the pick among all points") {
  const auto points = sphere_points(3000);
  for (const Camera& camera : {orbit_camera(), orbit_camera(50.0f)}) {
    const ScreenGrid grid(points->positions, camera, kViewport, 4.0f);
    for (float x = 0.0f; x <= 800.0f; x += 37.0f)
      for (float y = 0.0f; y <= 600.0f; y += 41.0f) {
        CAPTURE(x);
        CAPTURE(y);
        CHECK(pick_point(grid, points->positions, points->normals, camera, {x, y}, 12.0f) ==
              pick_point(points->positions, points->normals, camera, kViewport, {x, y}, 12.0f));
      }
  }
}

TEST_CASE("selection: a screen grid knows the view it was made for, and refuses a bad one") {
  const auto points = sphere_points(100);
  Camera camera = orbit_camera();
  const ScreenGrid grid(points->positions, camera, kViewport, 4.0f);
  CHECK(grid.made_for(camera, kViewport));
  CHECK_FALSE(grid.made_for(camera, Viewport{0, 0, 640, 480}));
  camera.orbit_by(1.0f, 0.0f);
  CHECK_FALSE(grid.made_for(camera, kViewport));
  CHECK_THROWS_AS(ScreenGrid(points->positions, camera, Viewport{0, 0, 0, 480}, 4.0f), std::invalid_argument);
  CHECK_THROWS_AS(ScreenGrid(points->positions, camera, kViewport, 0.0f), std::invalid_argument);
  CHECK_THROWS_AS(ScreenGrid(points->positions, camera, kViewport, std::nanf("")), std::invalid_argument);
}
