// The editor's worker on `amls bench`'s drag (core/run/drag_bench.hpp): a
// sphere of radius 0.3 at about N points with three fixed handles and one
// pulled outwards by 0.5 h per move, each move posted as the UI posts a drag
// (BeginDrag, then MoveHandles) once the snapshot of the last one is out, as
// a UI that sends a move every frame would. It reports the time from a move's
// post to its snapshot (what the user waits for: the session's step plus the
// worker's snapshot) beside the session's own step time, so that the
// worker's share shows.
//   amls_editor_bench [points] [threads] [always|local] [moves]
//   (defaults: 1000000 2 local 40)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/editor/editor_worker.hpp"
#include "core/run/drag_bench.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

double maximum(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace amls;
  using namespace amls::editor;
  const std::size_t points = argc > 1 ? std::stoul(argv[1]) : 1000000;
  const int threads = argc > 2 ? std::stoi(argv[2]) : 2;
  const std::string policy = argc > 3 ? argv[3] : "local";
  const std::size_t moves = argc > 4 ? std::stoul(argv[4]) : 40;
  constexpr double kRadius = 0.3;
  // As the drag benchmark: a grid-resampled sphere has about 0.83 area / h^2 points.
  const double h = std::sqrt(0.83 * 4.0 * std::numbers::pi * kRadius * kRadius / static_cast<double>(points));
  const Vec<3> center = Vec<3>::Zero();

  WorkerOptions options;
  options.threads = threads;
  EditorWorker worker(options);
  auto wait = [&] {
    if (!worker.wait_until_idle(std::chrono::minutes(10))) throw std::runtime_error("the worker did not finish");
  };
  const Clock::time_point load_start = Clock::now();
  worker.post(command::LoadShape{3, kRadius, points, h});
  worker.post(command::SetResampling{true, ResamplePolicy::parse(policy)});
  for (const Vec<3>& handle : drag_handles(center, kRadius, 0.0, 0)) worker.post(command::AddHandle{handle});
  worker.post(command::BeginDrag{});
  wait();
  std::printf("editor worker: %zu points, h = %.6g, %d threads, --resample %s; load and start %.2f s\n",
              worker.snapshot()->points->input_count, h, threads, policy.c_str(),
              std::chrono::duration<double>(Clock::now() - load_start).count());

  // The first move resamples the loaded points whole (the session's start) unless the worker did while it
  // waited (under local: then "load and start" holds it); the others are the drag's steps.
  std::vector<double> wall_ms, step_ms, rest_ms;
  double first_ms = 0.0;
  for (std::size_t k = 1; k <= moves; ++k) {
    const Clock::time_point start = Clock::now();
    const std::uint64_t sequence = worker.post(command::MoveHandles{drag_handles(center, kRadius, 0.5 * h, k), {}});
    while (worker.snapshot()->processed < sequence) std::this_thread::sleep_for(std::chrono::microseconds(200));
    const double wall = 1e3 * std::chrono::duration<double>(Clock::now() - start).count();
    if (k == 1) {
      first_ms = wall;
      continue;
    }
    const double step = 1e3 * worker.snapshot()->last.timings.total();
    wall_ms.push_back(wall);
    step_ms.push_back(step);
    rest_ms.push_back(wall - step);
  }
  wait();
  for (const Message& m : worker.take_messages())
    if (m.level != Message::Level::info) std::printf("worker says: %s\n", m.text.c_str());
  std::printf("first move: %.0f ms\n", first_ms);
  std::printf("the other %zu moves: wall median %.1f ms, max %.1f ms; the session's step median %.1f ms, max %.1f ms\n",
              wall_ms.size(), median(wall_ms), maximum(wall_ms), median(step_ms), maximum(step_ms));
  std::printf("the worker's share beyond the session's step (each move's wall minus its step): median %.1f ms, max "
              "%.1f ms\n",
              median(rest_ms), maximum(rest_ms));
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "amls_editor_bench: %s\n", e.what());
  return 1;
}
