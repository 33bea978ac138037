#pragma once
// A small persistent pool for data-parallel loops. Work is split into equal
// contiguous blocks, one per thread, so a loop whose iterations write only their
// own outputs gives the same result for any thread count.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace amls {

class ThreadPool {
 public:
  // threads <= 0 means one thread per hardware core.
  explicit ThreadPool(int threads = 1);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body(begin, end, block) for `threads()` contiguous blocks covering
  // [0, n), the calling thread taking block 0, and returns when all are done.
  // The first exception thrown by a block is rethrown here.
  void parallel_for(std::size_t n, const std::function<void(std::size_t, std::size_t, int)>& body);

 private:
  void worker_loop(int block);
  void run_block(int block);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(std::size_t, std::size_t, int)>* body_ = nullptr;
  std::size_t n_ = 0;
  std::size_t generation_ = 0;
  int pending_ = 0;
  bool stopping_ = false;
  std::exception_ptr error_;
};

}  // namespace amls
