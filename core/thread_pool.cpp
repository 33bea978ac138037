#include "core/thread_pool.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

namespace amls {

namespace {

// What a sub-range aims to take under a cancellation check: short enough that
// a cancel is honoured promptly, long enough that the polls and the body's
// per-call set-up stay a negligible share of the work.
constexpr double kSubrangeSeconds = 1e-3;

}  // namespace

ThreadPool::ThreadPool(int threads) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int block = 1; block < threads; ++block) workers_.emplace_back([this, block] { worker_loop(block); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& w : workers_) w.join();
}

void ThreadPool::run_range(const Body& body, std::size_t begin, std::size_t end, int block) {
  if (!check_) {
    if (begin < end) body(begin, end, block);
    return;
  }
  using Clock = std::chrono::steady_clock;
  // The items' cost is unknown: start with one item, then size each sub-range
  // by the rate the previous one measured, at most doubling, so that a run of
  // cheap items does not make an overlong sub-range over costly ones. A
  // sub-range too quick for the clock measures 0 s and simply doubles.
  std::size_t size = 1;
  for (std::size_t b = begin; b < end;) {
    if (cancelled_.load(std::memory_order_relaxed)) return;
    if (check_()) {
      cancelled_.store(true, std::memory_order_relaxed);
      return;
    }
    const std::size_t e = b + std::min(size, end - b);
    const Clock::time_point start = Clock::now();
    body(b, e, block);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double fitted = static_cast<double>(e - b) * kSubrangeSeconds / seconds;
    size = static_cast<std::size_t>(std::clamp(fitted, 1.0, 2.0 * static_cast<double>(size)));
    b = e;
  }
}

void ThreadPool::run_block(int block) {
  const std::size_t blocks = static_cast<std::size_t>(threads());
  const std::size_t b = static_cast<std::size_t>(block);
  try {
    run_range(*body_, n_ * b / blocks, n_ * (b + 1) / blocks, block);
  } catch (...) {
    std::lock_guard lock(mutex_);
    if (!error_) error_ = std::current_exception();
  }
}

void ThreadPool::parallel_for(std::size_t n, const Body& body) {
  cancelled_.store(false, std::memory_order_relaxed);
  if (workers_.empty() || n < 2) {
    run_range(body, 0, n, 0);
  } else {
    {
      std::lock_guard lock(mutex_);
      body_ = &body;
      n_ = n;
      pending_ = static_cast<int>(workers_.size());
      error_ = nullptr;
      ++generation_;
    }
    wake_.notify_all();
    run_block(0);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    body_ = nullptr;
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }
  if (cancelled_.load(std::memory_order_relaxed)) throw Cancelled();
}

void ThreadPool::worker_loop(int block) {
  std::size_t seen = 0;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    run_block(block);
    {
      std::lock_guard lock(mutex_);
      --pending_;
    }
    done_.notify_one();
  }
}

}  // namespace amls
