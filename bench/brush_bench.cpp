// What a brush stroke costs the editor's UI thread on a large surface: a
// Fibonacci sphere of `points` points seen whole in a 1000x700 view, a stroke
// of `dabs` cursor moves across its front with a brush of 4 h (h the points'
// spacing), each move picking the point under the cursor and painting the
// points within the brush's sphere about it, as RegionTool does; and the pick
// alone, as the brush's outline follows the cursor before a press. Both look
// the points up in a screen grid (screen_grid.hpp), made once for the view:
// its time is given apart. The median of the moves.
//   amls_brush_bench [points] [dabs]   (defaults: 1000000 40)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "app/editor/brush_stroke.hpp"
#include "app/editor/picking.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) { return 1e3 * std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::shared_ptr<const amls::PreparedPoints> sphere(std::size_t count) {
  auto points = std::make_shared<amls::PreparedPoints>();
  points->positions.resize(count);
  points->normals.resize(count);
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(count);
    const double r = std::sqrt(1.0 - z * z), a = golden * static_cast<double>(i);
    const glm::vec3 p(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), static_cast<float>(z));
    points->positions[i] = p;
    points->normals[i] = p;
  }
  points->input_count = count;
  points->spacing = std::sqrt(4.0 * std::numbers::pi / static_cast<double>(count));
  return points;
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace amls;
  using namespace amls::editor;
  const std::size_t count = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int dabs = argc > 2 ? std::stoi(argv[2]) : 40;
  if (count == 0 || dabs < 1) throw std::invalid_argument("usage: amls_brush_bench [points > 0] [dabs > 0]");
  const auto points = sphere(count);
  const Viewport viewport{0, 0, 1000, 700};
  Camera camera = Camera::orbit();
  camera.fit(BoundingSphere{glm::vec3(0.0f), 1.0f}, viewport.aspect());
  const float radius = 4.0f * static_cast<float>(points->spacing), pick_px = 12.0f;
  const auto pixel_of = [&](int k) {
    return glm::vec2(350.0f + 300.0f * static_cast<float>(k) / static_cast<float>(dabs), 330.0f);
  };

  const Clock::time_point gridded = Clock::now();
  const ScreenGrid grid(points->positions, camera, viewport, pick_px / 3.0f);
  const double grid_ms = ms_since(gridded);
  std::vector<double> hover_ms;
  for (int k = 0; k < dabs; ++k) {
    const Clock::time_point start = Clock::now();
    if (!pick_point(grid, points->positions, points->normals, camera, pixel_of(k), pick_px))
      throw std::runtime_error("the hover found no point");
    hover_ms.push_back(ms_since(start));
  }

  const Clock::time_point pressed = Clock::now();
  BrushStroke stroke(points, radius);
  if (!stroke.paint(grid, camera, pixel_of(0), pick_px)) throw std::runtime_error("the press painted nothing");
  const double press_ms = ms_since(pressed);
  std::vector<double> dab_ms;
  for (int k = 1; k < dabs; ++k) {
    const Clock::time_point start = Clock::now();
    if (!stroke.paint(grid, camera, pixel_of(k), pick_px)) throw std::runtime_error("a dab painted nothing");
    dab_ms.push_back(ms_since(start));
  }
  std::printf("points %zu, brush %.2f h, %d dabs: %zu painted (%.0f per dab)\n", count, 4.0, dabs,
              stroke.painted().size(), static_cast<double>(stroke.painted().size()) / dabs);
  std::printf(
      "screen grid (once per view) %.3f ms; hover (pick only) median %.3f ms; press %.3f ms; dab median %.3f ms\n",
      grid_ms, median(hover_ms), press_ms, median(dab_ms));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_brush_bench: %s\n", e.what());
  return 1;
}
