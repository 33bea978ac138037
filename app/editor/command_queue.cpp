#include "app/editor/command_queue.hpp"

#include <algorithm>

namespace amls::editor {

std::uint64_t CommandQueue::push(Command command) {
  std::uint64_t sequence = 0;
  {
    std::lock_guard lock(mutex_);
    if (closed_) return 0;
    sequence = next_sequence_++;
    if (cancels_running_work(command, running_is_load_)) ++epoch_;
    if (supersedes_queued_moves(command))
      std::erase_if(queue_,
                    [](const QueuedCommand& q) { return std::holds_alternative<command::MoveHandles>(q.command); });
    auto* move = std::get_if<command::MoveHandles>(&command);
    auto* last = queue_.empty() ? nullptr : std::get_if<command::MoveHandles>(&queue_.back().command);
    if (move && last) {  // the newest move wins whole: its handles' and its regions' places
      *last = std::move(*move);
      queue_.back().sequence = sequence;
      return sequence;
    }
    queue_.push_back(QueuedCommand{sequence, 0, std::move(command)});
  }
  ready_.notify_one();
  return sequence;
}

std::optional<QueuedCommand> CommandQueue::pop() {
  std::unique_lock lock(mutex_);
  ready_.wait(lock, [&] { return closed_ || !queue_.empty(); });
  if (closed_) return std::nullopt;
  QueuedCommand next = std::move(queue_.front());
  queue_.pop_front();
  next.epoch = epoch_;
  running_is_load_ = is_load(next.command);
  return next;
}

void CommandQueue::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ++epoch_;
    queue_.clear();
  }
  ready_.notify_all();
}

std::uint64_t CommandQueue::cancel_epoch() const {
  std::lock_guard lock(mutex_);
  return epoch_;
}

std::size_t CommandQueue::size() const {
  std::lock_guard lock(mutex_);
  return queue_.size();
}

bool CommandQueue::closed() const {
  std::lock_guard lock(mutex_);
  return closed_;
}

}  // namespace amls::editor
