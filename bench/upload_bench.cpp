// What the editor pays to show a new point set of a million points: the
// worker's share (prepare_points on its pool: the checks, the float
// conversion, the bounds) and the UI thread's (the GL upload, each finished
// with glFinish before the clock stops), on the current machine's OpenGL
// (OSMesa's llvmpipe). The upload is timed into a new store (the first point
// set, or one past the store) and into the store of the last set, persistently
// mapped where the context can and with glBufferSubData. The median of
// `repeats` runs each.
//   amls_upload_bench [points] [threads] [repeats]   (defaults: 1000000 2 9)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/util/thread_pool.hpp"
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
  const int threads = argc > 2 ? std::max(1, std::atoi(argv[2])) : 2;
  const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 9;
  OffscreenContext context(64, 64);
  std::printf("amls_upload_bench: %zu points, %s, median of %d\n", count, context.renderer().c_str(), repeats);
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, count);
  const double spacing = 1e-3;

  PreparedPoints prepared;
  const double alone_ms = median_ms(repeats, [&] { prepared = prepare_points<3>(sphere, spacing); });
  ThreadPool pool(threads);
  const double pooled_ms = median_ms(repeats, [&] { prepared = prepare_points<3>(sphere, spacing, &pool); });
  std::printf("prepare_points: %.1f ms alone, %.1f ms on %d threads\n", alone_ms, pooled_ms, threads);

  for (const BufferUpdate update : {BufferUpdate::best_available, BufferUpdate::sub_data}) {
    const double new_store_ms = median_ms(repeats, [&] {
      PointBuffers fresh(update);
      fresh.upload(prepared);
      glFinish();
    });
    PointBuffers buffers(update);
    buffers.upload(prepared);
    const double same_store_ms = median_ms(repeats, [&] {
      buffers.upload(prepared);
      glFinish();
    });
    std::printf("GL upload, %s: %.1f ms into a new store, %.1f ms into the last one\n",
                buffers.persistent() ? "persistently mapped" : "glBufferSubData", new_store_ms, same_store_ms);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_upload_bench: %s\n", e.what());
  return 1;
}
