#include "core/util/thread_pool.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

namespace amls {

namespace {

// What a sub-range aims to take under a cancellation check: short enough that
// a cancel is honoured promptly, long enough that the polls and the body's
// per-call set-up stay a negligible share of the work.
constexpr double kSubrangeSeconds = 1e-3;

// How long a waiting thread spins before it blocks. Longer than the serial
// stretches between the loops of a step (tens of microseconds), so that a step
// runs without sleeping; short enough that an idle pool (the editor's between
// two edits) goes to sleep at once on a human scale.
constexpr std::chrono::microseconds kSpin{500};

// The calling thread's time inside parallel loops, in clock ticks, and how
// many parallel_for calls it is inside (a loop's body may run another pool's).
thread_local std::chrono::steady_clock::duration parallel_time{0};
thread_local int parallel_depth = 0;

// Adds the time from construction to destruction to parallel_time, unless an
// enclosing loop of the same thread already counts it.
class ParallelTimeScope {
 public:
  explicit ParallelTimeScope(bool counted) : counted_(counted && parallel_depth == 0) {
    ++parallel_depth;
    if (counted_) start_ = std::chrono::steady_clock::now();
  }
  ~ParallelTimeScope() {
    --parallel_depth;
    if (counted_) parallel_time += std::chrono::steady_clock::now() - start_;
  }
  ParallelTimeScope(const ParallelTimeScope&) = delete;
  ParallelTimeScope& operator=(const ParallelTimeScope&) = delete;

 private:
  bool counted_;
  std::chrono::steady_clock::time_point start_;
};

ThreadPool::CancelCheck& default_cancel_check() {
  static ThreadPool::CancelCheck check;
  return check;
}

}  // namespace

void ThreadPool::set_default_cancel_check(CancelCheck check) { default_cancel_check() = std::move(check); }

double ThreadPool::parallel_seconds_of_this_thread() {
  return std::chrono::duration<double>(parallel_time).count();
}

ThreadPool::ThreadPool(int threads) : check_(default_cancel_check()) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int worker = 1; worker < threads; ++worker) workers_.emplace_back([this] { worker_loop(); });
}

ThreadPool::~ThreadPool() {
  stopping_.store(true);
  notify(start_);
  for (auto& w : workers_) w.join();
}

template <typename Ready>
void ThreadPool::await(Signal& signal, Ready&& ready) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline = Clock::now() + kSpin;
  for (int spins = 1;; ++spins) {
    if (ready()) return;
    // Yielding rather than pausing: on a busy machine a spinning thread must
    // not keep the core from the thread it waits for (or from other work);
    // on an idle one the yield returns at once.
    std::this_thread::yield();
    if (spins % 64 == 0 && Clock::now() > deadline) break;
  }
  // Counting ourselves before the last look (both sequentially consistent)
  // means that whoever makes `ready` true afterwards sees a sleeper and wakes
  // us through the mutex, so the wake-up cannot be lost.
  std::unique_lock lock(mutex_);
  signal.sleepers.fetch_add(1);
  signal.blocked.wait(lock, ready);
  signal.sleepers.fetch_sub(1);
}

void ThreadPool::notify(Signal& signal) {
  if (signal.sleepers.load() == 0) return;
  // Taking the mutex orders us after a sleeper's last look: it is then waiting.
  { std::lock_guard lock(mutex_); }
  signal.blocked.notify_all();
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

void ThreadPool::parallel_for(std::size_t n, Body body) {
  // A loop of one item is serial work, whatever the pool.
  const ParallelTimeScope timed(n >= 2);
  cancelled_.store(false, std::memory_order_relaxed);
  if (workers_.empty() || n < 2) {
    run_range(body, 0, n, 0);
  } else {
    // No block of the last loop runs any more and none of this one can be
    // claimed before the store to loop_, which publishes these plain writes.
    body_ = &body;
    n_ = n;
    finished_.store(0, std::memory_order_relaxed);
    const std::uint32_t generation = static_cast<std::uint32_t>(loop_.load() >> 32) + 1;
    loop_.store(std::uint64_t{generation} << 32);
    notify(start_);
    run_blocks(generation);
    // Every block is claimed; wait for those other threads are running.
    await(done_, [this] { return finished_.load() == threads(); });
    body_ = nullptr;
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }
  if (cancelled_.load(std::memory_order_relaxed)) throw Cancelled();
}

void ThreadPool::run_blocks(std::uint32_t generation) {
  const auto blocks = static_cast<std::uint32_t>(threads());
  for (std::uint64_t loop = loop_.load();;) {
    // Claim the next block, unless this loop is over (then loop_ names a later one).
    do {
      if (static_cast<std::uint32_t>(loop >> 32) != generation || static_cast<std::uint32_t>(loop) >= blocks) return;
    } while (!loop_.compare_exchange_weak(loop, loop + 1));
    run_block(static_cast<int>(static_cast<std::uint32_t>(loop)));
    // The increment releases the block's writes to the owner, which reads
    // finished_ before it returns.
    if (finished_.fetch_add(1) + 1 == threads()) notify(done_);
    loop = loop_.load();
  }
}

void ThreadPool::worker_loop() {
  std::uint32_t seen = 0;
  while (true) {
    await(start_, [&] { return stopping_.load() || static_cast<std::uint32_t>(loop_.load() >> 32) != seen; });
    if (stopping_.load()) return;
    seen = static_cast<std::uint32_t>(loop_.load() >> 32);
    run_blocks(seen);
  }
}

}  // namespace amls
