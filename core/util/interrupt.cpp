#include "core/util/interrupt.hpp"

#include <atomic>
#include <csignal>

#include "core/util/thread_pool.hpp"

namespace amls {

namespace {

// Written by the signal handler: only a lock-free atomic may be.
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int) { interrupted.store(true, std::memory_order_relaxed); }

}  // namespace

void request_interrupt() { interrupted.store(true, std::memory_order_relaxed); }

bool interrupt_requested() { return interrupted.load(std::memory_order_relaxed); }

void stop_work_on_interrupt() {
  ThreadPool::set_default_cancel_check([] { return interrupt_requested(); });
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // The handler runs once; then SIGINT has its default action again (end the process).
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
}

}  // namespace amls
