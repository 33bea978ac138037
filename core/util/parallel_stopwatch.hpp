#pragma once
// Wall time, and how much of it the calling thread spent inside parallel
// loops (ThreadPool::parallel_for over two items or more). Measured on one
// thread, the rest is the serial share that bounds the speed-up from more
// threads (Amdahl): a run with serial share s goes at most 1 / s times faster.
#include <algorithm>
#include <chrono>

#include "core/util/thread_pool.hpp"

namespace amls {

struct ParallelLap {
  double wall = 0.0;      // seconds
  double parallel = 0.0;  // seconds of `wall` inside parallel loops
  // The share of the wall time outside parallel loops: 1 with none (also
  // for a lap too short for the clock), 0 for nothing but parallel loops.
  double serial_share() const { return wall > 0.0 ? std::clamp(1.0 - parallel / wall, 0.0, 1.0) : 1.0; }
  ParallelLap& operator+=(const ParallelLap& o) {
    wall += o.wall;
    parallel += o.parallel;
    return *this;
  }
};

// Laps since construction or the last lap(), on the thread that calls lap().
class ParallelStopwatch {
 public:
  ParallelLap lap() {
    const auto now = std::chrono::steady_clock::now();
    const double parallel = ThreadPool::parallel_seconds_of_this_thread();
    const ParallelLap out{std::chrono::duration<double>(now - wall_).count(), parallel - parallel_};
    wall_ = now;
    parallel_ = parallel;
    return out;
  }

 private:
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  double parallel_ = ThreadPool::parallel_seconds_of_this_thread();
};

}  // namespace amls
