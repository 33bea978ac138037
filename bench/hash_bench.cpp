// Hash() alone (AmlsSurface::hash_points: the point index's build and the
// points reordered by cell) on the sphere of `amls bench`'s step, as a step
// meets it: the points in the order the last hash left them, moved a little
// (a small rotation) since. Prints the fastest and the median of the runs.
//   amls_hash_bench [points] [threads] [runs]
//   (defaults: 1000000 1 15)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>
#include <string>
#include <vector>

#include "core/geometry/shapes.hpp"
#include "core/surface/amls_surface.hpp"
#include "core/util/stopwatch.hpp"

int main(int argc, char** argv) try {
  using namespace amls;
  const std::size_t points = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int threads = argc > 2 ? std::stoi(argv[2]) : 1;
  const int runs = argc > 3 ? std::stoi(argv[3]) : 15;
  if (points < 2 || threads < 1 || runs < 1) throw std::invalid_argument("points >= 2, threads >= 1, runs >= 1");
  const double radius = 0.3;
  const Vec<3> center(0.5, 0.5, 0.5);
  // The spacing of bench_sphere_step (core/run/bench_suite.cpp).
  const double h = std::sqrt(0.83 * 4.0 * std::numbers::pi * radius * radius / static_cast<double>(points));
  AmlsSurface<3> surface(Grid<3>(Vec<3>::Zero(), h), AmlsParameters{});
  surface.set_points(sample_sphere(center, radius, points));
  ThreadPool pool(threads);
  surface.hash_points(pool);  // the storage a step finds
  std::vector<double> seconds;
  const double angle = 0.01;
  for (int run = 0; run < runs; ++run) {
    PointSet<3>& moved = surface.mutable_points();
    for (Vec<3>& p : moved.positions) {
      const Vec<3> d = p - center;
      p = center + Vec<3>(std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                          std::sin(angle) * d.x() + std::cos(angle) * d.y(), d.z());
    }
    Stopwatch clock;
    surface.hash_points(pool);
    seconds.push_back(clock.lap());
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("hash of %zu points, %d thread%s: fastest %.4f s, median %.4f s (%d runs)\n", surface.points().size(),
              threads, threads == 1 ? "" : "s", seconds.front(), seconds[seconds.size() / 2], runs);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_hash_bench: %s\n", e.what());
  return 1;
}
