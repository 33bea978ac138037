// What the editor pays to show a new point set of a million points, as
// EditorWorker and EditorApp::take_snapshot do it: the worker's share
// (prepare_points on its pool: the checks, the float conversion, the bounds;
// into new memory, and into the memory of points let go, as during a drag)
// and the UI thread's (the points and their colours handed to the renderer,
// finished with glFinish before the clock stops), on the current machine's
// headless OpenGL (EGL or OSMesa; AMLS_GL_BACKEND chooses). The UI's share is
// timed into the buffers of the last point set (a drag's steps) and into new
// ones (a load), persistently
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
#include "render/point_data.hpp"
#include "render/splat_renderer.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// The median milliseconds of `repeats` calls of `run`, each after an untimed call of `setup`.
double median_ms(int repeats, const std::function<void()>& run, const std::function<void()>& setup = [] {}) {
  std::vector<double> ms;
  for (int k = 0; k < repeats; ++k) {
    setup();
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
  std::printf("amls_upload_bench: %zu points, %s, median of %d\n", count, context.info().summary().c_str(), repeats);
  const PointSet<3> sphere = sample_sphere(Vec<3>::Zero(), 1.0, count);
  const double spacing = 1e-3;

  PreparedPoints points;
  const double alone_ms = median_ms(repeats, [&] { points = prepare_points<3>(sphere, spacing); });
  ThreadPool pool(threads);
  const double pooled_ms = median_ms(repeats, [&] { points = prepare_points<3>(sphere, spacing, &pool); });
  // As the worker's PointRecycler does during a drag: into the memory of points let go.
  const double reused_ms = median_ms(repeats, [&] { prepare_points<3>(sphere, spacing, &pool, points); });
  std::printf("worker, per point set: prepare_points %.1f ms alone, %.1f ms on %d threads, %.1f ms so into reused "
              "memory\n",
              alone_ms, pooled_ms, threads, reused_ms);
  const PreparedPoints few = prepare_points<3>(sample_sphere(Vec<3>::Zero(), 1.0, 10), spacing);
  // The spacing's colours, as the worker makes them once per measurement.
  const PreparedScalars colors = prepare_scalars(std::vector<double>(count, 1.0), count, {});

  for (const BufferUpdate update : {BufferUpdate::best_available, BufferUpdate::sub_data}) {
    auto adopt = [&](SplatRenderer& renderer) {
      renderer.set_points(points);
      renderer.set_scalars(colors);
      glFinish();
    };
    SplatRenderer renderer(update);
    adopt(renderer);
    const double last_ms = median_ms(repeats, [&] { adopt(renderer); });
    // Ten points before: their buffers are far too small for the next set.
    const double new_ms = median_ms(repeats, [&] { adopt(renderer); }, [&] { renderer.set_points(few); });
    std::printf("UI thread, per snapshot (points and colours), %s: %.1f ms into the last buffers, %.1f ms into new ones\n",
                renderer.persistent_point_buffers() ? "persistently mapped" : "glBufferSubData", last_ms, new_ms);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_upload_bench: %s\n", e.what());
  return 1;
}
