#pragma once
// Small scenes shared by the tests.
#include <cmath>
#include <numbers>

#include "core/run/scene.hpp"

namespace amls::test {

// The unit circle of 250 points (h = 0.024, the clover2d scene's grid) pulled out at its
// four diagonals to radius 1.3 in `steps` steps: one stage of four handles.
inline Scene<2> pulled_circle(std::size_t steps) {
  Scene<2> scene;
  scene.name = "pulled circle";
  scene.shape.type = ShapeType::circle;
  scene.shape.points = 250;
  scene.grid_spacing = 0.024;
  std::vector<Vec<2>> start, pulled;
  for (int i = 0; i < 4; ++i) {
    const double a = (0.25 + 0.5 * i) * std::numbers::pi;
    start.emplace_back(std::cos(a), std::sin(a));
    pulled.push_back(1.3 * start.back());
  }
  scene.history.begin_stage(start);
  scene.history.add_target(pulled, steps);
  return scene;
}

}  // namespace amls::test
