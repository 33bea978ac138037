#include <doctest/doctest.h>

#include <thread>

#include "app/editor/point_recycler.hpp"
#include "core/geometry/shapes.hpp"

using namespace amls;
using namespace amls::editor;

TEST_CASE("the worker's points to draw reuse the memory of those let go, and are what prepare_points makes") {
  ThreadPool pool(2);
  PointRecycler recycler;
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, 3000);
  const PointSet<3> smaller = sample_sphere(Vec<3>::Zero(), 0.5, 2000);
  auto first = recycler.prepare<3>(sphere, 0.05, pool);
  CHECK(first->positions == prepare_points<3>(sphere, 0.05).positions);
  const glm::vec3* first_memory = first->positions.data();
  // Held (by a snapshot the UI shows): the next set gets memory of its own.
  auto second = recycler.prepare<3>(smaller, 0.05, pool);
  CHECK(second->positions.data() != first_memory);
  // Let go, on another thread as the UI does: the next set goes into its memory.
  std::thread([held = std::move(first)]() mutable { held.reset(); }).join();
  const auto third = recycler.prepare<3>(smaller, 0.04, pool);
  CHECK(third->positions.data() == first_memory);
  const PreparedPoints alone = prepare_points<3>(smaller, 0.04);
  CHECK(third->positions == alone.positions);
  CHECK(third->normals == alone.normals);
  CHECK(third->input_count == alone.input_count);
  CHECK(third->spacing == alone.spacing);
  CHECK(third->bounds.radius == alone.bounds.radius);
  // Memory more than twice too large is not kept for a small set.
  second.reset();
  const PointSet<2> circle = sample_circle(Vec<2>::Zero(), 1.0, 100);
  const auto small = recycler.prepare<2>(circle, 0.06, pool);
  CHECK(small->dimension == 2);
  CHECK(small->positions.capacity() < 1000);
  CHECK(small->positions == prepare_points<2>(circle, 0.06).positions);
}

TEST_CASE("points to draw outlive their recycler") {
  ThreadPool pool(1);
  std::shared_ptr<const PreparedPoints> kept;
  {
    PointRecycler recycler;
    kept = recycler.prepare<2>(sample_circle(Vec<2>::Zero(), 1.0, 50), 0.1, pool);
  }
  CHECK(kept->size() == 50);
  kept.reset();  // returns to the spares the points still hold
}
