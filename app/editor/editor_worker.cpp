#include "app/editor/editor_worker.hpp"

#include <filesystem>
#include <sstream>
#include <utility>

#include "app/editor/initial_shape.hpp"
#include "app/editor/overloaded.hpp"
#include "app/editor/sampling_quality.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/mesh_export.hpp"
#include "core/run/scene.hpp"

namespace amls::editor {

namespace {

template <int D>
Vec<3> to_3d_vector(const Vec<D>& v) {
  Vec<3> out = Vec<3>::Zero();
  out.template head<D>() = v;
  return out;
}

std::string describe_count(std::size_t n, const char* what) { return std::to_string(n) + " " + what; }

// The session's surface as a mesh. While it is the opened closed mesh's
// (undeformed: its samples or their resamples), the grid vertices lie on the
// sides the input mesh says, as `amls resample --mesh` decides them
// (core/run/mesh_export.hpp): a closed mesh in, a closed mesh out.
template <int D>
MeshExport export_session_mesh(const std::string& path, EditSession<D>& s) {
  if constexpr (D == 3) {
    if (const TriangleMesh* closed = s.closed_input(); closed && !s.deformed())
      return export_surface_mesh(path, s.points(), s.grid(), s.settings().parameters(), s.settings().variant,
                                 s.pool().threads(), closed);
  }
  return export_surface_mesh(path, s.evaluable_surface(), s.settings().variant, s.pool());
}

}  // namespace

template <int D>
std::shared_ptr<const PreparedPoints> EditorWorker::drawable_points(EditSession<D>& s) {
  try {
    return recycler_.prepare<D>(s.points(), s.settings().spacing, s.pool());
  } catch (const std::exception& e) {
    message(Message::Level::error, std::string("Cannot show the points: ") + e.what());
    PreparedPoints none;
    none.dimension = D;
    none.spacing = s.settings().spacing;
    return std::make_shared<const PreparedPoints>(std::move(none));
  }
}

EditorWorker::EditorWorker(WorkerOptions options)
    : options_(options), snapshot_(std::make_shared<const Snapshot>()), thread_([this] { run(); }) {}

EditorWorker::~EditorWorker() {
  queue_.close();
  thread_.join();
}

std::uint64_t EditorWorker::post(Command command) {
  const std::uint64_t sequence = queue_.push(std::move(command));
  std::lock_guard lock(mutex_);
  posted_ = std::max(posted_, sequence);
  return sequence;
}

std::shared_ptr<const Snapshot> EditorWorker::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_;
}

WorkerStatus EditorWorker::status() const {
  std::lock_guard lock(mutex_);
  WorkerStatus status = status_;
  if (status.busy) status.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
  status.queued = queue_.size();
  return status;
}

std::vector<Message> EditorWorker::take_messages() {
  std::lock_guard lock(mutex_);
  return std::exchange(messages_, {});
}

bool EditorWorker::wait_until_idle(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return idle_.wait_for(lock, timeout, [&] { return processed_ >= posted_ && !status_.busy; });
}

void EditorWorker::message(Message::Level level, std::string text) {
  std::lock_guard lock(mutex_);
  messages_.push_back(Message{level, std::move(text)});
}

void EditorWorker::set_phase(const char* name, int index, int count) {
  std::lock_guard lock(mutex_);
  status_.activity = name;
  status_.phase = index;
  status_.phases = count;
}

void EditorWorker::run() {
  while (std::optional<QueuedCommand> queued = queue_.pop()) {
    {
      std::lock_guard lock(mutex_);
      status_ = WorkerStatus{true, describe(queued->command), 0, 1, 0.0, 0};
      started_ = Clock::now();
    }
    try {
      execute(*queued);
    } catch (const std::exception& e) {
      message(Message::Level::error, e.what());
    }
    publish(queued->sequence);
    {
      std::lock_guard lock(mutex_);
      processed_ = queued->sequence;
    }
    if (options_.on_publish) options_.on_publish();
    // Still busy: wait_until_idle() returns with this done.
    if (queue_.size() == 0) work_while_waiting();
    {
      std::lock_guard lock(mutex_);
      status_ = WorkerStatus{};
    }
    idle_.notify_all();
  }
}

WorkControl EditorWorker::control_while_waiting() {
  return WorkControl{[this] { return queue_.size() > 0 || queue_.closed(); },
                     [this](const char* name, int index, int count) { set_phase(name, index, count); }};
}

void EditorWorker::work_while_waiting() {
  if (std::holds_alternative<std::monostate>(session_)) return;
  bool changed = false;
  on_session([&](auto& s) {
    const EditResult prepared = s.prepare_local(control_while_waiting());
    note_result(prepared);
    changed = prepared.changed || s.map_exactly(control_while_waiting());
  });
  if (changed) {
    std::uint64_t processed = 0;
    {
      std::lock_guard lock(mutex_);
      processed = processed_;
    }
    publish(processed);
    if (options_.on_publish) options_.on_publish();
  }
  if (queue_.size() == 0) refresh_spacing();
}

void EditorWorker::refresh_spacing() {
  if (!derived_ || derived_->dimension == 0 || derived_->spacing_version == derived_->points_version) return;
  set_phase("measuring the spacing", 0, 1);
  on_session([&](auto& s) {
    CancelScope stop_for_commands(s.pool(), control_while_waiting().cancelled);
    try {
      SamplingQuality quality = sampling_quality(s.points(), s.settings().spacing, s.pool());
      auto snapshot = std::make_shared<Snapshot>(*derived_);
      snapshot->generation = ++generation_;
      auto measured = std::make_shared<SpacingPerPoint>();
      measured->values = std::move(quality.spacing_h);
      measured->drawn = prepare_scalars(measured->values, snapshot->points->input_count, snapshot->points->source_index);
      snapshot->spacing_h = std::move(measured);
      snapshot->spacing = quality.stats;
      snapshot->spacing_version = snapshot->points_version;
      derived_ = snapshot;
      {
        std::lock_guard lock(mutex_);
        snapshot_ = std::move(snapshot);
      }
      if (options_.on_publish) options_.on_publish();
    } catch (const Cancelled&) {
      // A command came: it goes first; the spacing is measured after it.
    }
  });
}

void EditorWorker::start(const InitialShape& shape) {
  // Build the new session first: if that fails, the current one stays.
  Session next;
  if (shape.dimension() == 2)
    next = std::make_unique<EditSession<2>>(shape, options_.threads);
  else
    next = std::make_unique<EditSession<3>>(shape, options_.threads);
  session_ = std::move(next);
  name_ = shape.name;
  ++load_id_;
  has_last_ = false;
  total_ = PhaseTimings{};
  steps_ = 0;
  resamples_ = 0;
  step_times_.clear();
  for (const std::string& warning : shape.warnings) message(Message::Level::warning, warning);
  if (!shape.opened.empty()) message(Message::Level::info, shape.opened);
  std::ostringstream text;
  text << "Loaded " << shape.name << ": " << describe_count(shape.points.size(), "points") << ", " << shape.dimension()
       << "D, h = " << shape.settings.spacing;
  if (!shape.coverage.empty() && !shape.coverage_loss) text << "; " << shape.coverage;
  message(Message::Level::info, text.str());
  // Last, so that the status line shows it, in red.
  if (shape.coverage_loss) message(Message::Level::error, shape.coverage);
}

void EditorWorker::note_result(const EditResult& result) {
  if (result.cancelled) ++cancelled_;
  resamples_ += result.resamples;
  if (!result.has_stats) return;
  has_last_ = true;
  last_ = result.stats;
  total_ += result.stats.timings;
  if (!result.stepped) return;
  ++steps_;
  step_times_.push_back(Clock::now());
}

template <typename Edit>
void EditorWorker::on_session(Edit&& edit) {
  const bool loaded = std::visit(Overloaded{[](std::monostate&) { return false; },
                                            [&](auto& session) {
                                              edit(*session);
                                              return true;
                                            }},
                                 session_);
  if (!loaded) message(Message::Level::warning, "Nothing is loaded yet: open a file or a shape first");
}

WorkControl EditorWorker::control_for(std::uint64_t epoch) {
  return WorkControl{[this, epoch] {
                       if (options_.on_poll) options_.on_poll();
                       return queue_.cancel_epoch() != epoch;
                     },
                     [this](const char* name, int index, int count) { set_phase(name, index, count); }};
}

void EditorWorker::load_file(const command::LoadFile& load, const WorkControl& control) {
  const std::string& path = load.path;
  try {
    // On a pool of its own (a session owns its pool), stopped as the command's other work is.
    ThreadPool pool(options_.threads);
    CancelScope stop(pool, control.cancelled);
    start(load_initial_shape(path, pool, control.phase, load.estimate_normals));
  } catch (const Cancelled&) {
    message(Message::Level::info, "Opening " + path + " was stopped" +
                                      (std::holds_alternative<std::monostate>(session_) ? "" : " (the current surface is kept)"));
  } catch (const std::exception& e) {
    // The readers' messages start with the file's path (and name the key in a scene): say it once.
    const std::string why = e.what();
    message(Message::Level::error,
            "Cannot open " + (why.rfind(path, 0) == 0 ? why : path + ": " + why) +
                (std::holds_alternative<std::monostate>(session_) ? "" : " (the current surface is kept)"));
  }
}

void EditorWorker::export_points(const std::string& path) {
  on_session([&](auto& s) {
    try {
      s.map_exactly(WorkControl{});  // a local drag's end, if the worker has not waited since
      // With the session's h, which opening the file again takes.
      write_point_set(path, s.points(), format_from_extension(path), s.settings().spacing);
      message(Message::Level::info, "Exported " + describe_count(s.points().size(), "points") + " to " + path);
    } catch (const std::exception& e) {
      message(Message::Level::error, std::string("Export failed (any previous file is intact): ") + e.what());
    }
  });
}

void EditorWorker::export_mesh(const std::string& path) {
  on_session([&](auto& s) {
    try {
      s.map_exactly(WorkControl{});
      const MeshExport mesh = export_session_mesh(path, s);
      std::string note;
      if (s.closed_input() && s.deformed() && !mesh.topology.closed())
        note = "; where F is undefined it was not capped: the closed input mesh, whose inside caps it, no longer "
               "describes the deformed surface (undo back to the opened surface to export it closed)";
      message(mesh.topology.closed() ? Message::Level::info : Message::Level::warning,
              "Exported a mesh of " + mesh.summary() + " to " + path + note);
    } catch (const std::exception& e) {
      message(Message::Level::error, std::string("Mesh export failed (any previous file is intact): ") + e.what());
    }
  });
}

void EditorWorker::save_scene(const std::string& path) {
  on_session([&](auto& s) {
    try {
      const std::string name = std::filesystem::path(path).stem().string();
      write_scene(path, recorded_scene(s.recording(), path, name));
      const std::string note = s.recording().exact() ? "" : " - not an exact replay: " + s.recording().inexact_reason();
      message(s.recording().exact() ? Message::Level::info : Message::Level::warning,
              "Saved the scene " + path + " (" + describe_count(s.recording().steps().size(), "steps") + ")" + note);
    } catch (const std::exception& e) {
      message(Message::Level::error, std::string("Save Scene failed: ") + e.what());
    }
  });
}

void EditorWorker::execute(const QueuedCommand& queued) {
  const WorkControl control = control_for(queued.epoch);
  using namespace command;
  std::visit(
      Overloaded{
          [&](const LoadFile& c) { load_file(c, control); },
          [&](const LoadShape& c) {
            start(c.dimension == 3 ? make_sphere(c.radius, c.points, c.spacing)
                                   : make_circle(c.radius, c.points, c.spacing));
          },
          [&](const AddHandle& c) {
            on_session([&](auto& s) { s.add_handle(c.position.head<std::decay_t<decltype(s)>::dimension>()); });
          },
          [&](const RemoveHandle& c) { on_session([&](auto& s) { s.remove_handle(c.index); }); },
          [&](const BeginDrag&) { on_session([&](auto& s) { s.begin_drag(); }); },
          [&](const MoveHandles& c) {
            on_session([&](auto& s) {
              constexpr int D = std::decay_t<decltype(s)>::dimension;
              if (c.positions.size() != s.handles().size() ||
                  (!c.regions.empty() && c.regions.size() != s.regions().size())) {
                message(Message::Level::warning, "A handle move was dropped: the handles changed meanwhile");
                return;
              }
              if (c.regions.empty()) {
                note_result(s.move_handles(from_3d<D>(c.positions), control));
                return;
              }
              std::vector<RegionMotion<D>> motions;
              for (const RegionMove& move : c.regions) motions.push_back(motion_from<D>(move));
              note_result(s.move_handles(from_3d<D>(c.positions), motions, control));
            });
          },
          [&](const AddRegion& c) {
            on_session([&](auto& s) {
              constexpr int D = std::decay_t<decltype(s)>::dimension;
              s.add_region(from_3d<D>(c.members), s.settings().spacing, c.pinned);
            });
          },
          [&](const ReplaceRegion& c) {
            on_session([&](auto& s) {
              constexpr int D = std::decay_t<decltype(s)>::dimension;
              s.replace_region(c.index, from_3d<D>(c.members));
            });
          },
          [&](const RemoveRegion& c) { on_session([&](auto& s) { s.remove_region(c.index); }); },
          [&](const PinRegion& c) { on_session([&](auto& s) { s.set_region_pinned(c.index, c.pinned); }); },
          [&](const CancelDrag&) { on_session([&](auto& s) { s.cancel_drag(); }); },
          [&](const SetVariant& c) { on_session([&](auto& s) { note_result(s.set_variant(c.variant, control)); }); },
          [&](const SetGrid& c) {
            on_session([&](auto& s) { note_result(s.set_grid(c.spacing, c.radius_factor, control)); });
          },
          [&](const SetDeformation& c) { on_session([&](auto& s) { s.set_deformation(c.kind, c.alpha); }); },
          [&](const SetResampling& c) { on_session([&](auto& s) { s.set_resampling(c.enabled, c.policy); }); },
          [&](const SetCurveTracing& c) { curve_enabled_ = c.enabled; },
          [&](const Undo&) {
            on_session([&](auto& s) {
              if (!s.undo()) message(Message::Level::info, "Nothing to undo");
            });
          },
          [&](const Redo&) {
            on_session([&](auto& s) {
              if (!s.redo()) message(Message::Level::info, "Nothing to redo");
            });
          },
          [&](const Reset&) { on_session([&](auto& s) { s.reset(); }); },
          [&](const Export& c) { export_points(c.path); }, [&](const ExportMesh& c) { export_mesh(c.path); }, [&](const SaveScene& c) { save_scene(c.path); }},
      queued.command);
}

void EditorWorker::publish(std::uint64_t processed) {
  auto snapshot = std::make_shared<Snapshot>();
  snapshot->generation = ++generation_;
  snapshot->processed = processed;
  snapshot->load_id = load_id_;
  snapshot->name = name_;
  snapshot->has_last = has_last_;
  snapshot->last = last_;
  snapshot->total = total_;
  snapshot->steps = steps_;
  snapshot->resamples = resamples_;
  snapshot->cancelled = cancelled_;
  const Clock::time_point now = Clock::now();
  while (!step_times_.empty() && now - step_times_.front() > std::chrono::seconds(1)) step_times_.pop_front();
  snapshot->steps_per_second = static_cast<double>(step_times_.size());

  std::visit(Overloaded{[](std::monostate&) {},
                        [&](auto& session) {
                          auto& s = *session;
                          constexpr int D = std::decay_t<decltype(s)>::dimension;
                          snapshot->dimension = D;
                          snapshot->points_version = s.version();
                          snapshot->settings = s.settings();
                          snapshot->grid_origin = to_3d_vector<D>(s.grid().origin());
                          for (const Vec<D>& h : s.handles()) snapshot->handles.push_back(to_3d_vector<D>(h));
                          for (const RegionHandle<D>& r : s.regions()) snapshot->regions.push_back(view_of<D>(r));
                          snapshot->can_undo = s.can_undo();
                          snapshot->can_redo = s.can_redo();
                          snapshot->recorded_steps = s.recording().steps().size();
                          snapshot->replay_note = s.recording().inexact_reason();
                          snapshot->replay_arguments = s.recording().replay_arguments();
                          // Points, quality and curve are derived once per point set.
                          const bool same = derived_ && derived_version_ == s.version() && derived_load_ == load_id_;
                          if (same) {
                            snapshot->points = derived_->points;
                            snapshot->spacing_h = derived_->spacing_h;
                            snapshot->spacing = derived_->spacing;
                            snapshot->spacing_version = derived_->spacing_version;
                            snapshot->curve = derived_->curve;
                          } else {
                            snapshot->points = drawable_points(s);
                            // The spacing is measured by refresh_spacing(); until then the last one stands in
                            // (its colours, when they are in the order of the new drawable points).
                            if (derived_ && derived_load_ == load_id_ && derived_->spacing_h &&
                                derived_->spacing_h->values.size() == s.points().size() &&
                                derived_->points->source_index == snapshot->points->source_index) {
                              snapshot->spacing_h = derived_->spacing_h;
                              snapshot->spacing = derived_->spacing;
                              snapshot->spacing_version = derived_->spacing_version;
                            }
                            if (derived_ && derived_load_ == load_id_) snapshot->curve = derived_->curve;
                          }
                          if constexpr (D == 2) {
                            const bool stale = curve_version_ != s.version() || derived_load_ != load_id_;
                            const bool due = queue_.size() == 0 ||
                                             now - last_trace_ > std::chrono::duration<double>(options_.curve_interval);
                            if (!curve_enabled_) {
                              snapshot->curve.clear();
                              curve_version_ = ~std::uint64_t{0};
                            } else if (stale && due) {
                              snapshot->curve = trace_curve(s.evaluable_surface(), s.pool()).segments;
                              curve_version_ = s.version();
                              last_trace_ = now;
                            }
                          }
                          derived_version_ = s.version();
                        }},
             session_);
  derived_load_ = load_id_;
  derived_ = snapshot;
  std::lock_guard lock(mutex_);
  snapshot_ = std::move(snapshot);
}

}  // namespace amls::editor
