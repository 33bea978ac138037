#pragma once
// A small persistent pool for data-parallel loops. Work is split into equal
// contiguous blocks, one per thread, so a loop whose iterations write only their
// own outputs gives the same result for any thread count.
//
// Running work can be stopped inside a loop: while the pool has a cancellation
// check (set_cancel_check, or a CancelScope), each block runs as consecutive
// sub-ranges and the check is polled before each one.
//
// Loops can be short (a 2D step runs several of about 100 microseconds each),
// so the hand-offs avoid the kernel where they can: a waiting thread spins for
// a bounded time, watching an atomic, before it blocks on a condition variable,
// and the other side only takes the mutex to wake it when someone blocked.
// Blocks are claimed, not assigned: a thread that is late (asleep, or off its
// core on a busy machine) finds its block done by the others rather than
// holding up the loop. Which thread runs a block changes nothing in it.
//
// Every pool counts, per calling thread, the wall time spent inside its
// parallel loops (two clock reads per parallel_for call), so that a run can
// tell how much of its time is serial (core/util/parallel_stopwatch.hpp).
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace amls {

// A block's own entry in a per-block array that the blocks write at the same
// time (a list they append to, say): a cache line to itself, since entries
// sharing a line would bounce it between the cores.
template <typename T>
struct alignas(64) OwnCacheLine {
  T value;
};

// Thrown by ThreadPool::parallel_for when its cancellation check asked it to stop.
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "the work was cancelled"; }
};

class ThreadPool {
 public:
  // A reference to the loop body, body(begin, end, block), valid for the
  // parallel_for call: unlike a std::function it never allocates.
  class Body {
   public:
    template <typename Fn, typename = std::enable_if_t<!std::is_same_v<std::decay_t<Fn>, Body>>>
    Body(Fn&& fn)  // NOLINT(google-explicit-constructor): lambdas convert implicitly, as to std::function
        : fn_(const_cast<void*>(static_cast<const void*>(&fn))), call_([](void* f, std::size_t b, std::size_t e, int k) {
            (*static_cast<std::remove_reference_t<Fn>*>(f))(b, e, k);
          }) {}
    void operator()(std::size_t begin, std::size_t end, int block) const { call_(fn_, begin, end, block); }

   private:
    void* fn_;
    void (*call_)(void*, std::size_t, std::size_t, int);
  };
  // True once the work should stop. Called concurrently from every thread of the
  // pool, so it must be thread-safe, and cheap (it runs about every millisecond).
  using CancelCheck = std::function<bool()>;

  // threads <= 0 means one thread per hardware core.
  explicit ThreadPool(int threads = 1);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body for `threads()` contiguous blocks covering [0, n), each run
  // by one thread (the calling thread too), and returns when all are done.
  // Block k covers the same range in every call with the same n, so that two
  // loops over the same items can share per-block state (a sort's counts).
  // The first exception thrown by a block is rethrown here.
  //
  // Without a cancellation check, body(begin, end, block) runs once per
  // non-empty block. With one, each block runs as consecutive sub-ranges
  // body(b0, b1, block), body(b1, b2, block), ... in increasing order, sized
  // by the time they take (about a millisecond each), so a body must give the
  // same result called once or in pieces. The check is polled before each
  // sub-range; once it returns true every thread stops at its next poll and
  // parallel_for throws Cancelled (after all of them stopped; a block's own
  // exception wins). What the body wrote until then stays written.
  void parallel_for(std::size_t n, Body body);

  // For serial loops of the pool's owner: throws Cancelled if the check says
  // stop (call it every few thousand items).
  void poll_cancel() const {
    if (check_ && check_()) throw Cancelled();
  }
  // Installs the check polled by parallel_for (an empty one removes it). Not
  // while a parallel_for runs.
  void set_cancel_check(CancelCheck check) { check_ = std::move(check); }
  const CancelCheck& cancel_check() const { return check_; }

  // The check every pool constructed afterwards starts with (empty: none), for
  // a program whose work all stops on one flag, as the command line's on
  // Ctrl+C (core/util/interrupt.hpp). Call it before any pool exists.
  static void set_default_cancel_check(CancelCheck check);

  // Seconds the calling thread has spent inside parallel loops since it
  // started: parallel_for calls over at least two items, of any pool, the
  // outermost only when a loop's body runs another. A loop counts whatever
  // its thread count (with one thread it is the work that more threads would
  // share), so on one thread the rest of a run's time is its serial part.
  static double parallel_seconds_of_this_thread();

 private:
  // One direction of hand-off: a thread waits until `ready` holds.
  struct Signal {
    std::condition_variable blocked;
    std::atomic<int> sleepers = 0;  // threads blocked (or about to block) on `blocked`
  };
  template <typename Ready>
  void await(Signal& signal, Ready&& ready);
  // Wakes the threads blocked on `signal`; call after making their condition true.
  void notify(Signal& signal);

  void worker_loop();
  // Claims and runs blocks of loop `generation` until none is left.
  void run_blocks(std::uint32_t generation);
  void run_block(int block);
  void run_range(const Body& body, std::size_t begin, std::size_t end, int block);

  std::vector<std::thread> workers_;
  std::mutex mutex_;  // guards error_ and the blocking half of await()
  Signal start_;      // workers wait for a new loop (or stopping_)
  Signal done_;       // the owner waits for finished_ == threads()
  // The current loop, published by the store to loop_.
  const Body* body_ = nullptr;
  std::size_t n_ = 0;
  // The loop's generation (high 32 bits) and its next unclaimed block (low 32).
  std::atomic<std::uint64_t> loop_ = 0;
  std::atomic<int> finished_ = 0;  // blocks of the current loop done
  std::atomic<bool> stopping_ = false;
  std::exception_ptr error_;
  CancelCheck check_;
  // Set by the first thread whose poll said stop, so that the others stop at their next poll.
  std::atomic<bool> cancelled_ = false;
};

// Gives a pool a cancellation check for a scope and puts the one it had back at
// the end, so that later work (e.g. the next command) does not poll a stale one.
class CancelScope {
 public:
  CancelScope(ThreadPool& pool, ThreadPool::CancelCheck check) : pool_(pool), previous_(pool.cancel_check()) {
    pool_.set_cancel_check(std::move(check));
  }
  ~CancelScope() { pool_.set_cancel_check(std::move(previous_)); }
  CancelScope(const CancelScope&) = delete;
  CancelScope& operator=(const CancelScope&) = delete;

 private:
  ThreadPool& pool_;
  ThreadPool::CancelCheck previous_;
};

}  // namespace amls
