// What the editor pays to show a new point set of a million points: the
// worker's share (copying the session's points into the snapshot) and the UI
// thread's (the checks and the float conversion, then the GL upload; each
// upload is finished with glFinish before the clock stops), on the current
// machine's OpenGL (OSMesa's llvmpipe). The median of `repeats` runs each.
//   amls_upload_bench [points] [repeats]   (defaults: 1000000 9)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "render/gl.hpp"
#include "render/offscreen_context.hpp"
#include "render/point_buffers.hpp"
#include "render/point_data.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// The median milliseconds of `repeats` calls of `run`.
double median_ms(int repeats, const std::function<void()>& run) {
  std::vector<double> ms;
  for (int k = 0; k < repeats; ++k) {
    const Clock::time_point start = Clock::now();
    run();
    ms.push_back(1e3 * std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace amls;
  const std::size_t count = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 9;
  OffscreenContext context(64, 64);
  std::printf("amls_upload_bench: %zu points, %s, median of %d\n", count, context.renderer().c_str(), repeats);
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, count);
  const double spacing = 1e-3;

  PointSet<3> copy;
  const double copy_ms = median_ms(repeats, [&] {
    copy = PointSet<3>();  // as the worker's snapshot: a new set each time
    copy = sphere;
  });
  PreparedPoints prepared;
  const double prepare_ms = median_ms(repeats, [&] { prepared = prepare_points<3>(sphere, spacing); });
  PointBuffers buffers;
  const double upload_ms = median_ms(repeats, [&] {
    buffers.upload(prepared);
    glFinish();
  });
  std::printf("worker: copy the points %.1f ms\n", copy_ms);
  std::printf("UI thread: prepare %.1f ms, GL upload %.1f ms\n", prepare_ms, upload_ms);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_upload_bench: %s\n", e.what());
  return 1;
}
