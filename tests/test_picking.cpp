#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "app/editor/picking.hpp"
#include "view_fixtures.hpp"

using namespace amls;
using namespace amls::editor;
using namespace amls::test;

TEST_CASE("the ray through a point's pixel passes through the point") {
  for (const Camera& c : {planar_camera(), orbit_camera(), orbit_camera(35.0f)}) {
    const glm::vec3 p(0.3f, -0.2f, c.mode == Camera::Mode::planar ? 0.0f : 0.4f);
    const Ray ray = pixel_ray(c, kViewport, window_of(c, p));
    const glm::vec3 to_p = p - ray.origin;
    const float off_ray = glm::length(to_p - glm::dot(to_p, ray.direction) * ray.direction);
    CHECK(off_ray < 1e-4f);
  }
}

TEST_CASE("the plane point under a pixel inverts the projection - in 2D it lies in z = 0") {
  const Camera planar = planar_camera();
  const glm::vec2 pixel = window_of(planar, glm::vec3(0.25f, 0.5f, 0.0f));
  const std::optional<glm::vec3> p = plane_point(planar, kViewport, pixel, glm::vec3(0.0f));
  REQUIRE(p);
  CHECK(p->x == doctest::Approx(0.25f).epsilon(1e-4));
  CHECK(p->y == doctest::Approx(0.5f).epsilon(1e-4));
  CHECK(p->z == 0.0f);
  const Camera orbit = orbit_camera(20.0f);
  const glm::vec3 anchor(0.1f, 0.2f, 0.3f);
  const std::optional<glm::vec3> q = plane_point(orbit, kViewport, window_of(orbit, anchor), anchor);
  REQUIRE(q);
  CHECK(glm::length(*q - anchor) < 1e-4f);
}

TEST_CASE("a point is picked within the radius, the nearest on screen - none farther away") {
  const Camera c = planar_camera();
  const std::vector<glm::vec3> points{{0.0f, 0.0f, 0.0f}, {0.02f, 0.0f, 0.0f}, {0.5f, 0.5f, 0.0f}};
  const glm::vec2 near_second = window_of(c, points[1]) + glm::vec2(1.0f, 1.0f);
  CHECK(pick_point(points, {}, c, kViewport, near_second, 6.0f) == std::optional<std::size_t>(1));
  CHECK(!pick_point(points, {}, c, kViewport, window_of(c, points[2]) + glm::vec2(20.0f, 0.0f), 6.0f));
}

TEST_CASE("zoomed in, a click anywhere on a splat picks its point") {
  const Camera c = orbit_camera();
  const std::vector<glm::vec3> points{{0.0f, 0.0f, 0.5f}};
  const glm::vec2 off_centre = window_of(c, glm::vec3(0.08f, 0.0f, 0.5f));  // tens of pixels away
  CHECK(!pick_point(points, {}, c, kViewport, off_centre, 6.0f));
  CHECK(pick_point(points, {}, c, kViewport, off_centre, 6.0f, 0.1f) == std::optional<std::size_t>(0));
}

TEST_CASE("a click on a closed surface picks its front, not the back point behind it") {
  const Camera c = orbit_camera();  // looking down -z: the front is at z = +1
  const std::vector<glm::vec3> points{{0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}};
  const std::vector<glm::vec3> normals{{0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}};
  const glm::vec2 centre(400.0f, 300.0f);
  CHECK(pick_point(points, normals, c, kViewport, centre, 6.0f) == std::optional<std::size_t>(1));
  CHECK(pick_point(points, {}, c, kViewport, centre, 6.0f) == std::optional<std::size_t>(1));
}

TEST_CASE("the handle nearest to the cursor is picked") {
  const Camera c = planar_camera();
  const std::vector<glm::vec3> handles{{-0.5f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}};
  CHECK(pick_handle(handles, c, kViewport, window_of(c, handles[1]) + glm::vec2(3.0f, 0.0f), 10.0f) ==
        std::optional<std::size_t>(1));
  CHECK(!pick_handle(handles, c, kViewport, glm::vec2(400.0f, 300.0f), 10.0f));
}

TEST_CASE("a dragged handle follows the cursor with its grab offset, or only along a locked axis") {
  const Camera c = planar_camera();
  const glm::vec3 start(0.5f, 0.0f, 0.0f), grab(0.01f, -0.01f, 0.0f);
  const glm::vec2 pixel = window_of(c, glm::vec3(0.8f, 0.3f, 0.0f));
  const std::optional<glm::vec3> free = drag_position(c, kViewport, pixel, start, grab, AxisLock::none);
  REQUIRE(free);
  CHECK(free->x == doctest::Approx(0.81f).epsilon(1e-3));
  CHECK(free->y == doctest::Approx(0.29f).epsilon(1e-3));
  const std::optional<glm::vec3> along_x = drag_position(c, kViewport, pixel, start, grab, AxisLock::x);
  REQUIRE(along_x);
  CHECK(along_x->x == doctest::Approx(0.81f).epsilon(1e-3));
  CHECK(along_x->y == 0.0f);
  // 3D: the drag stays in the plane through the start parallel to the screen.
  const Camera orbit = orbit_camera();
  const glm::vec3 start3(0.2f, 0.1f, 0.7f);
  const std::optional<glm::vec3> moved = drag_position(
      orbit, kViewport, window_of(orbit, start3) + glm::vec2(40.0f, -25.0f), start3, glm::vec3(0.0f), AxisLock::none);
  REQUIRE(moved);
  CHECK(moved->z == doctest::Approx(0.7f).epsilon(1e-4));
  CHECK(moved->x > start3.x);
  CHECK(moved->y > start3.y);
}
