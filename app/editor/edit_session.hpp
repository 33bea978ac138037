#pragma once
// One editing session on one surface: the DeformingSurface, its handles, the
// undo and redo stacks and the recording for Save Scene. It belongs to the
// editor's worker thread (see editor_worker.hpp) and is not thread-safe. No GL.
//
// A handle move is one step of the paper's loop (section 4): the MLS
// deformation from the handles' previous positions to the new ones, then a
// resample if the resample policy asks for one - the same calls, in the same
// order, with the same decisions, as `amls deform`, so that a saved session
// replays exactly (session_recording.hpp).
//
// Under the `local` policy a LocalDeformingSurface carries the points and
// their strain from step to step (core/run/local_deforming_surface.hpp): each
// step maps them and resamples only where strained. The DeformingSurface
// takes a copy only when something needs it (evaluation, export, another
// policy): copying and hashing a million points would cost more than the step.
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "app/editor/session_recording.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/run/local_deforming_surface.hpp"

namespace amls::editor {

// How an edit reports its phases and learns that it should stop.
struct WorkControl {
  // Polled before each phase and, through the surface's thread pool, about
  // every millisecond inside one: from every pool thread at once, so it must be
  // thread-safe.
  std::function<bool()> cancelled;
  std::function<void(const char* phase, int index, int count)> phase;  // the phase about to run
};

struct EditResult {
  bool changed = false;  // the point set, the handles or a parameter changed
  // Stopped, between phases or inside one. The point set is as before the edit;
  // so is everything else for a handle move, while a variant or grid change
  // keeps its new value, unresampled.
  bool cancelled = false;
  bool stepped = false;    // a deformation step was taken
  std::size_t resamples = 0;  // resamples the edit did
  bool has_stats = false;  // the surface did work, summed in `stats`
  StepStats stats;
};

template <int D>
class EditSession {
 public:
  static constexpr int dimension = D;

  // The undo history keeps the newest states that fit in this many bytes
  // (and always the newest one): a few at a million points, hundreds on a
  // small shape.
  static constexpr std::size_t kDefaultUndoBytes = std::size_t{256} << 20;

  // Throws std::invalid_argument if the shape does not have dimension D, or
  // its settings are out of range.
  EditSession(const InitialShape& shape, int threads, std::size_t undo_bytes = kDefaultUndoBytes);

  // In a fixed order for each version(): the local loop's while it holds them.
  const PointSet<D>& points() const { return local_in_sync() ? local_->points() : surface_->points(); }
  const std::vector<Vec<D>>& handles() const { return handles_; }
  const std::vector<RegionHandle<D>>& regions() const { return regions_; }
  const SurfaceSettings& settings() const { return settings_; }
  const SessionRecording<D>& recording() const { return recording_; }
  const Grid<D>& grid() const { return surface_->surface().grid(); }
  // Changes whenever the point set does.
  std::uint64_t version() const { return version_; }
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  // The opened file's input mesh where it is closed (InitialShape::closed_mesh), else null.
  const TriangleMesh* closed_input() const { return closed_input_.get(); }
  // A deformation step was taken since the shape was opened or reset (undo
  // can take it back): then the input mesh no longer describes the surface,
  // as it does the opened points and their resamples.
  bool deformed() const { return !recording_.steps().empty(); }

  // The surface of the current points, ready for evaluation (the pseudo-normals recomputed).
  const AmlsSurface<D>& evaluable_surface();
  ThreadPool& pool() { return surface_->pool(); }

  // Handles. Adding and removing make the state before them an undo point.
  void add_handle(const Vec<D>& position);
  void remove_handle(std::size_t index);  // throws std::out_of_range
  // Region handles (core/deform/region_handle.hpp), likewise undoable: a new
  // region of these members (positions where the region is now) and reach,
  // at rest; one removed; one pinned or let go. Throw std::invalid_argument
  // (a bad region) or std::out_of_range (no such region).
  void add_region(std::vector<Vec<D>> members, double reach, bool pinned);
  void replace_region(std::size_t index, std::vector<Vec<D>> members);  // its members edited: at rest again
  void remove_region(std::size_t index);
  void set_region_pinned(std::size_t index, bool pinned);

  // A drag: begin_drag() makes the current state an undo point; each
  // move_handles() is one step to the new positions (one per handle; throws
  // std::invalid_argument for another count); cancel_drag() goes back to the
  // undo point and drops it.
  void begin_drag();
  EditResult move_handles(std::vector<Vec<D>> to, const WorkControl& control);
  // The same with the regions moved too, one motion per region (a pinned
  // region's must stay its own; std::invalid_argument otherwise).
  EditResult move_handles(std::vector<Vec<D>> to, const std::vector<RegionMotion<D>>& motions,
                          const WorkControl& control);
  bool cancel_drag();
  // Under `local`, what the first step would do first, now: the points
  // resampled whole into the local loop (the worker calls it once it waits
  // for commands, so that the first drag on a large surface starts at once).
  // Nothing to do under another policy or once the loop holds the points.
  EditResult prepare_local(const WorkControl& control);
  // Under `local`, the end of a drag (the worker calls it once it waits for
  // commands): the points the last step left interpolated on the lattice are
  // mapped exactly (LocalDeformingSurface::map_exactly; `amls deform --resample
  // local` ends alike) and the point set is a new version. False if there was
  // nothing to do or the control stopped it (then nothing changed).
  bool map_exactly(const WorkControl& control);

  // Parameters. The variant and the grid resample the current surface at once
  // (no deformation) and are undoable; kind, alpha and resampling (on or off,
  // and the policy) apply to the next steps and are kept by undo. set_grid and
  // set_resampling throw std::invalid_argument for a bad value, and set_grid
  // for one that would make millions of points, changing nothing.
  EditResult set_variant(Variant variant, const WorkControl& control);
  EditResult set_grid(double spacing, double radius_factor, const WorkControl& control);
  void set_deformation(MlsKind kind, double alpha);
  void set_resampling(bool enabled, const ResamplePolicy& policy);

  bool undo();
  bool redo();
  // Back to the initial shape and handles with the current parameters (undoable).
  void reset();

 private:
  // What an undo restores.
  struct State {
    PointSet<D> points;
    std::vector<Vec<D>> handles;
    std::vector<RegionHandle<D>> regions;
    SurfaceSettings settings;  // only h, Delta / h and the variant are restored
    std::vector<float> strain;  // under `local`, each point's (empty otherwise)
    bool settled = false;
    SessionRecording<D> recording;
    // What the state holds in memory, about: its points, handles and recorded steps.
    std::size_t bytes() const;
  };
  // set_grid refuses a spacing that would resample the surface into more points than this.
  static constexpr double kMaxExpectedPoints = 5e6;

  std::unique_ptr<DeformingSurface<D>> make_surface(const SurfaceSettings& settings) const;
  State current_state() const;
  void restore(const State& state);
  // Throws std::out_of_range if there is no region `index`.
  void check_region(std::size_t index) const;
  // Makes the current state an undo point, and forgets the redo states.
  void push_undo();
  // Appends to the undo states, dropping the oldest while they exceed the budget.
  void push_back_undo(State state);
  void pop_undo(bool newest);
  // After a stopped edit: the surface holds `before` again.
  void roll_back(PointSet<D> before);
  EditResult resample_now(const WorkControl& control);
  // The local loop, made for this grid and variant if there is none.
  LocalDeformingSurface<D>& local_loop();
  // Resamples the current points whole into the local loop (the start of `local`).
  void start_local(EditResult& result);
  // A handle move under the `local` policy.
  EditResult move_handles_locally(const MlsDeformation<D>& deformation, std::vector<Vec<D>> to,
                                  std::vector<RegionHandle<D>> regions_to, const WorkControl& control);
  // Whether steps resample under the `local` policy.
  bool resamples_locally() const {
    return settings_.resample && settings_.policy.kind == ResamplePolicy::Kind::local;
  }
  // Whether the local loop holds the current points (its strain is theirs).
  bool local_in_sync() const { return local_ && local_version_ == version_; }
  // surface_, holding the current points: copied from the local loop if a local step left it behind.
  DeformingSurface<D>& synced_surface();

  int threads_;
  std::shared_ptr<const TriangleMesh> closed_input_;
  State initial_;
  std::unique_ptr<DeformingSurface<D>> surface_;
  bool surface_behind_ = false;  // the local loop holds newer points than surface_ (it is in sync)
  std::unique_ptr<LocalDeformingSurface<D>> local_;  // made by the first step under `local`, for this grid and variant
  std::uint64_t local_version_ = ~std::uint64_t{0};  // the version whose points local_ holds
  std::vector<Vec<D>> handles_;
  std::vector<RegionHandle<D>> regions_;
  SurfaceSettings settings_;
  // The resample policy has had its say on the points: they are a resample's,
  // or a step's that the policy chose not to resample. Only the initial points
  // and those of a step taken with resampling off are not.
  bool settled_ = false;
  SessionRecording<D> recording_;
  std::deque<State> undo_, redo_;
  std::size_t undo_budget_;
  std::size_t undo_bytes_ = 0;  // of undo_'s states
  std::uint64_t version_ = 0;
  std::uint64_t normals_version_ = ~std::uint64_t{0};  // the version whose pseudo-normals are computed
};

extern template class EditSession<2>;
extern template class EditSession<3>;

}  // namespace amls::editor
