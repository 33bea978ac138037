#pragma once
// The editor's worker thread (docs: ../shared/DESIGN.md, "Threads in the
// editor"). It owns the session and its DeformingSurface and applies the UI's
// commands in order; after each it publishes an immutable snapshot. The UI
// only posts commands and reads snapshots, status and messages: it never waits
// for the worker. No GL.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <variant>
#include <vector>

#include "app/editor/command_queue.hpp"
#include "app/editor/edit_session.hpp"
#include "app/editor/point_recycler.hpp"
#include "app/editor/snapshot.hpp"

namespace amls::editor {

struct WorkerOptions {
  int threads = 1;  // the surface's thread pool
  // While commands wait, the 2D curve is traced at most this often (seconds);
  // it always is once the queue is empty.
  double curve_interval = 0.1;
  // Called on the worker thread after each snapshot or message (e.g. to wake the UI's event loop).
  std::function<void()> on_publish;
  // For tests: called each time running work asks whether it should stop
  // (before each phase, and about every millisecond inside one, on the pool's
  // threads), just before it asks. Lets a test post a command at a known point.
  std::function<void()> on_poll;
};

class EditorWorker {
 public:
  explicit EditorWorker(WorkerOptions options = {});
  // Closes the queue, stops running work (within about a millisecond of the
  // phase's work), puts its surface back and joins the thread.
  ~EditorWorker();
  EditorWorker(const EditorWorker&) = delete;
  EditorWorker& operator=(const EditorWorker&) = delete;

  // Queues a command; returns its sequence number (Snapshot::processed reaches it once applied).
  std::uint64_t post(Command command);

  // The newest snapshot (never null: an empty one before the first load).
  std::shared_ptr<const Snapshot> snapshot() const;
  WorkerStatus status() const;
  // The messages since the last call, oldest first.
  std::vector<Message> take_messages();

  // For tests and the command line: waits until every command posted so far is applied.
  bool wait_until_idle(std::chrono::milliseconds timeout) const;

 private:
  using Session = std::variant<std::monostate, std::unique_ptr<EditSession<2>>, std::unique_ptr<EditSession<3>>>;
  using Clock = std::chrono::steady_clock;

  void run();
  void execute(const QueuedCommand& queued);
  // How running work under the command of `epoch` polls for a stop and reports its phases.
  WorkControl control_for(std::uint64_t epoch);
  // Runs `edit(session)` on the session of either dimension, or says that nothing is loaded.
  template <typename Edit>
  void on_session(Edit&& edit);
  void load_file(const command::LoadFile& load, const WorkControl& control);
  void export_points(const std::string& path);
  void export_mesh(const std::string& path);
  void save_scene(const std::string& path);
  void start(const InitialShape& shape);
  void note_result(const EditResult& result);
  void publish(std::uint64_t processed);
  // The session's points made ready to draw; none (and a message) if they cannot be drawn.
  template <int D>
  std::shared_ptr<const PreparedPoints> drawable_points(EditSession<D>& s);
  // Once the queue is empty: under `local`, resamples newly loaded points
  // whole (what the first step would do first) or ends a drag (the points
  // mapped exactly); then measures the spacing. Each stops as soon as a
  // command is queued.
  void work_while_waiting();
  // The control of work done while waiting: it stops once a command is queued.
  WorkControl control_while_waiting();
  // Measures each point's spacing for the newest snapshot and publishes it
  // again with it; stops, leaving it stale, as soon as a command is queued.
  void refresh_spacing();
  void message(Message::Level level, std::string text);
  void set_phase(const char* name, int index, int count);

  WorkerOptions options_;
  CommandQueue queue_;

  // Worker thread only.
  Session session_;
  std::string name_;
  std::uint64_t load_id_ = 0;
  std::uint64_t generation_ = 0;
  bool curve_enabled_ = true;
  bool has_last_ = false;
  StepStats last_;
  PhaseTimings total_;
  std::size_t steps_ = 0;
  std::size_t resamples_ = 0;
  std::size_t cancelled_ = 0;
  std::deque<Clock::time_point> step_times_;
  // What the last snapshot derived from the points, kept while they do not change.
  std::uint64_t derived_version_ = ~std::uint64_t{0};
  std::uint64_t derived_load_ = 0;
  std::uint64_t curve_version_ = ~std::uint64_t{0};
  Clock::time_point last_trace_{};
  std::shared_ptr<const Snapshot> derived_;
  PointRecycler recycler_;

  // Shared with the UI thread.
  mutable std::mutex mutex_;
  mutable std::condition_variable idle_;
  std::shared_ptr<const Snapshot> snapshot_;
  WorkerStatus status_;
  Clock::time_point started_{};
  std::vector<Message> messages_;
  std::uint64_t posted_ = 0;
  std::uint64_t processed_ = 0;

  std::thread thread_;  // last: starts once everything above exists
};

}  // namespace amls::editor
