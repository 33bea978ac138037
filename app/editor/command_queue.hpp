#pragma once
// The queue between the editor's UI and its worker. Pushing never waits for
// work; the worker blocks in pop() until there is a command.
//
// - Coalescing: a MoveHandles pushed while the newest queued command is a
//   MoveHandles replaces its positions, so a drag queues at most one move and
//   the newest position wins.
// - Cancellation: a command for which cancels_running_work() holds bumps the
//   cancel epoch; the worker notes the epoch when it pops a command and stops
//   that command's work, between its phases or inside one, once the epoch has
//   moved on. Whether a command cancels depends on what was popped last (a
//   load is stopped only by another load or Esc).
// - A command for which supersedes_queued_moves() holds drops the moves still queued.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>

#include "app/editor/command.hpp"

namespace amls::editor {

struct QueuedCommand {
  std::uint64_t sequence = 0;  // increases with every push (a coalesced move takes the newest number)
  std::uint64_t epoch = 0;     // the cancel epoch when it was popped
  Command command;
};

class CommandQueue {
 public:
  // Returns the command's sequence number (0 once closed: the command is dropped).
  std::uint64_t push(Command command);
  // Blocks until a command is queued or the queue is closed; nullopt once closed.
  std::optional<QueuedCommand> pop();
  // Wakes pop() for good and drops what is queued; cancels running work.
  void close();

  std::uint64_t cancel_epoch() const;
  std::size_t size() const;
  bool closed() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<QueuedCommand> queue_;
  std::uint64_t next_sequence_ = 1;
  std::uint64_t epoch_ = 0;
  bool closed_ = false;
  bool running_is_load_ = false;  // what pop() handed out last
};

}  // namespace amls::editor
