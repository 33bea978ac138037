#pragma once
// A small persistent pool for data-parallel loops. Work is split into equal
// contiguous blocks, one per thread, so a loop whose iterations write only their
// own outputs gives the same result for any thread count.
//
// Running work can be stopped inside a loop: while the pool has a cancellation
// check (set_cancel_check, or a CancelScope), each block runs as consecutive
// sub-ranges and the check is polled before each one.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace amls {

// Thrown by ThreadPool::parallel_for when its cancellation check asked it to stop.
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "the work was cancelled"; }
};

class ThreadPool {
 public:
  using Body = std::function<void(std::size_t, std::size_t, int)>;
  // True once the work should stop. Called concurrently from every thread of the
  // pool, so it must be thread-safe, and cheap (it runs about every millisecond).
  using CancelCheck = std::function<bool()>;

  // threads <= 0 means one thread per hardware core.
  explicit ThreadPool(int threads = 1);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body for `threads()` contiguous blocks covering [0, n), the calling
  // thread taking block 0, and returns when all are done. The first exception
  // thrown by a block is rethrown here.
  //
  // Without a cancellation check, body(begin, end, block) runs once per
  // non-empty block. With one, each block runs as consecutive sub-ranges
  // body(b0, b1, block), body(b1, b2, block), ... in increasing order, sized
  // by the time they take (about a millisecond each), so a body must give the
  // same result called once or in pieces. The check is polled before each
  // sub-range; once it returns true every thread stops at its next poll and
  // parallel_for throws Cancelled (after all of them stopped; a block's own
  // exception wins). What the body wrote until then stays written.
  void parallel_for(std::size_t n, const Body& body);

  // For serial loops of the pool's owner: throws Cancelled if the check says
  // stop (call it every few thousand items).
  void poll_cancel() const {
    if (check_ && check_()) throw Cancelled();
  }
  // Installs the check polled by parallel_for (an empty one removes it). Not
  // while a parallel_for runs.
  void set_cancel_check(CancelCheck check) { check_ = std::move(check); }

 private:
  void worker_loop(int block);
  void run_block(int block);
  void run_range(const Body& body, std::size_t begin, std::size_t end, int block);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const Body* body_ = nullptr;
  std::size_t n_ = 0;
  std::size_t generation_ = 0;
  int pending_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
  CancelCheck check_;
  // Set by the first thread whose poll said stop, so that the others stop at their next poll.
  std::atomic<bool> cancelled_ = false;
};

// Gives a pool a cancellation check for a scope and removes it at the end, so
// that later work (e.g. the next command) does not poll a stale one.
class CancelScope {
 public:
  CancelScope(ThreadPool& pool, ThreadPool::CancelCheck check) : pool_(pool) {
    pool_.set_cancel_check(std::move(check));
  }
  ~CancelScope() { pool_.set_cancel_check({}); }
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  ThreadPool& pool_;
};

}  // namespace amls
