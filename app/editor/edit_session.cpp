#include "app/editor/edit_session.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/deform/mls_deformation.hpp"
#include "core/io/point_set_io.hpp"
#include "core/run/point_set_resampling.hpp"
#include "core/run/settle.hpp"

namespace amls::editor {

namespace {

// The shape's source, if the shape has dimension D.
template <int D>
const SceneShape<D>& source_of(const InitialShape& shape) {
  if (const SceneShape<D>* source = std::get_if<SceneShape<D>>(&shape.source)) return *source;
  throw std::invalid_argument("a " + std::to_string(shape.dimension()) + "D shape in a " + std::to_string(D) +
                              "D session");
}

// The shape's start regions, checked: a session moves only regions of its own dimension.
template <int D>
std::vector<RegionHandle<D>> regions_of(const InitialShape& shape) {
  if (const auto* regions = std::get_if<std::vector<RegionHandle<D>>>(&shape.regions)) return *regions;
  if (std::visit([](const auto& other) { return other.empty(); }, shape.regions)) return {};
  throw std::invalid_argument("regions of another dimension in a " + std::to_string(D) + "D session");
}

void add_stats(EditResult& result, const StepStats& stats) {
  if (!result.has_stats) {
    result.stats = stats;
    result.has_stats = true;
    return;
  }
  result.stats.timings += stats.timings;
  result.stats.points_after = stats.points_after;
  if (stats.normals.ok + stats.normals.failed() > 0) result.stats.normals = stats.normals;
  if (stats.resample.vertices > 0) result.stats.resample = stats.resample;
}

// Runs the phases of one edit, reporting each and stopping when asked: between
// phases, and inside one through the pool the phases run their loops on.
class Phases {
 public:
  Phases(const WorkControl& control, int count) : control_(control), count_(count) {}
  // Runs `work`, which calls next() before each phase and returns false if it
  // said stop, with the control's check on `pool`; false if the edit stopped.
  // The check is off the pool again afterwards, whatever happened.
  template <typename Work>
  bool run(ThreadPool& pool, Work&& work) {
    CancelScope scope(pool, control_.cancelled);
    try {
      return work();
    } catch (const Cancelled&) {
      return false;
    }
  }
  // False if the edit must stop before this phase.
  bool next(const char* name) {
    if (control_.cancelled && control_.cancelled()) return false;
    if (control_.phase) control_.phase(name, index_, count_);
    ++index_;
    return true;
  }
  // Whether a phase began: only then can the surface have changed.
  bool started() const { return index_ > 0; }

 private:
  const WorkControl& control_;
  int count_;
  int index_ = 0;
};

}  // namespace

template <int D>
EditSession<D>::EditSession(const InitialShape& shape, int threads, std::size_t undo_bytes)
    : threads_(threads),
      closed_input_(shape.closed_mesh),
      initial_{from_3d<D>(shape.points), from_3d<D>(shape.handles), regions_of<D>(shape), shape.settings, {}, false,
               SessionRecording<D>(source_of<D>(shape), shape.settings)},
      settings_(shape.settings),
      recording_(initial_.recording),
      undo_budget_(undo_bytes) {
  validate(settings_);
  surface_ = make_surface(settings_);
  restore(initial_);
}

template <int D>
std::unique_ptr<DeformingSurface<D>> EditSession<D>::make_surface(const SurfaceSettings& settings) const {
  validate(settings);
  // The grid `amls deform` builds for the scene: anchored by the initial shape's points.
  const Grid<D> grid = resampling_grid(initial_.points, settings.spacing, settings.radius_factor);
  return std::make_unique<DeformingSurface<D>>(grid, settings.parameters(), settings.variant,
                                               threads_);
}

template <int D>
typename EditSession<D>::State EditSession<D>::current_state() const {
  // The local loop's points in its own order, which its strain follows.
  if (local_in_sync())
    return State{local_->points(), handles_, regions_, settings_, local_->strain(), settled_, recording_};
  return State{surface_->points(), handles_, regions_, settings_, {}, settled_, recording_};
}

template <int D>
void EditSession<D>::restore(const State& state) {
  SurfaceSettings next = settings_;
  next.spacing = state.settings.spacing;
  next.radius_factor = state.settings.radius_factor;
  next.variant = state.settings.variant;
  if (!next.same_grid(settings_) || !surface_) surface_ = make_surface(next);
  if (!next.same_grid(settings_) || next.variant != settings_.variant) local_.reset();
  surface_->set_variant(next.variant);
  surface_->set_points(state.points);
  surface_behind_ = false;
  settings_ = next;
  handles_ = state.handles;
  regions_ = state.regions;
  settled_ = state.settled;
  recording_ = state.recording;
  ++version_;
  if (local_ && !state.strain.empty()) {
    local_->set_points(state.points, state.strain);
    local_version_ = version_;
  }
}

template <int D>
std::size_t EditSession<D>::State::bytes() const {
  std::size_t total = sizeof(State) +
                      (points.positions.size() + points.normals.size() + handles.size()) * sizeof(Vec<D>) +
                      regions.size() * sizeof(RegionHandle<D>) + strain.size() * sizeof(float);
  // The regions' members are shared among the states, and not counted.
  for (const RecordedStep<D>& step : recording.steps())
    total += sizeof(step) + (step.from.size() + step.to.size()) * sizeof(Vec<D>) +
             (step.regions_from.size() + step.regions_to.size()) * sizeof(RegionHandle<D>);
  return total;
}

template <int D>
void EditSession<D>::push_undo() {
  push_back_undo(current_state());
  redo_.clear();
}

template <int D>
void EditSession<D>::push_back_undo(State state) {
  undo_bytes_ += state.bytes();
  undo_.push_back(std::move(state));
  while (undo_.size() > 1 && undo_bytes_ > undo_budget_) pop_undo(false);
}

template <int D>
void EditSession<D>::pop_undo(bool newest) {
  State& state = newest ? undo_.back() : undo_.front();
  undo_bytes_ -= state.bytes();
  if (newest)
    undo_.pop_back();
  else
    undo_.pop_front();
}

template <int D>
void EditSession<D>::roll_back(PointSet<D> before) {
  // A phase stopped midway leaves the surface half-updated: points deformed in
  // place, pseudo-normals, the resampler's field. set_points replaces the points
  // and their hash and marks the pseudo-normals stale; the field is rebuilt by
  // the next Update_Function (Resampler::resample refuses one an interrupted
  // update left). The points are in the surface's cell order already, which
  // hashing keeps: the state is as if the edit never ran. The surface itself is
  // kept, warm: a fresh one would make the next step seconds slower at a
  // million points.
  surface_->set_points(std::move(before));
  normals_version_ = ~std::uint64_t{0};
}

template <int D>
DeformingSurface<D>& EditSession<D>::synced_surface() {
  if (surface_behind_) {
    surface_->set_points(local_->points());
    surface_behind_ = false;
  }
  return *surface_;
}

template <int D>
const AmlsSurface<D>& EditSession<D>::evaluable_surface() {
  DeformingSurface<D>& surface = synced_surface();
  if (normals_version_ != version_) {
    surface.refresh_normals();
    normals_version_ = version_;
  }
  return surface.surface();
}

template <int D>
void EditSession<D>::add_handle(const Vec<D>& position) {
  if (!position.allFinite()) throw std::invalid_argument("a handle needs a finite position");
  push_undo();
  handles_.push_back(position);
}

template <int D>
void EditSession<D>::remove_handle(std::size_t index) {
  if (index >= handles_.size())
    throw std::out_of_range("no handle " + std::to_string(index) + " to remove (there are " +
                            std::to_string(handles_.size()) + ")");
  push_undo();
  handles_.erase(handles_.begin() + static_cast<std::ptrdiff_t>(index));
}

template <int D>
void EditSession<D>::add_region(std::vector<Vec<D>> members, double reach, bool pinned) {
  auto region = std::make_shared<const PointRegion<D>>(std::move(members), reach);  // throws before any change
  push_undo();
  regions_.push_back(RegionHandle<D>{std::move(region), {}, pinned});
}

template <int D>
void EditSession<D>::replace_region(std::size_t index, std::vector<Vec<D>> members) {
  check_region(index);
  auto region = std::make_shared<const PointRegion<D>>(std::move(members), regions_[index].region->reach());
  push_undo();
  regions_[index] = RegionHandle<D>{std::move(region), {}, regions_[index].pinned};
}

template <int D>
void EditSession<D>::remove_region(std::size_t index) {
  check_region(index);
  push_undo();
  regions_.erase(regions_.begin() + static_cast<std::ptrdiff_t>(index));
}

template <int D>
void EditSession<D>::check_region(std::size_t index) const {
  if (index >= regions_.size())
    throw std::out_of_range("no region " + std::to_string(index) + " (there are " + std::to_string(regions_.size()) +
                            ")");
}

template <int D>
void EditSession<D>::set_region_pinned(std::size_t index, bool pinned) {
  check_region(index);
  if (regions_[index].pinned == pinned) return;
  push_undo();
  regions_[index].pinned = pinned;
}

template <int D>
void EditSession<D>::begin_drag() {
  push_undo();
}

template <int D>
bool EditSession<D>::cancel_drag() {
  if (undo_.empty()) return false;
  restore(undo_.back());
  pop_undo(true);
  return true;
}

template <int D>
bool EditSession<D>::map_exactly(const WorkControl& control) {
  if (!local_in_sync()) return false;
  Phases phases(control, 1);
  bool changed = false;
  const bool finished = phases.run(local_->pool(), [&] {
    if (!phases.next("mapping the points exactly")) return false;
    changed = local_->map_exactly();
    return true;
  });
  if (!finished || !changed) return false;
  ++version_;
  local_version_ = version_;
  surface_behind_ = true;
  return true;
}

template <int D>
EditResult EditSession<D>::move_handles(std::vector<Vec<D>> to, const WorkControl& control) {
  std::vector<RegionMotion<D>> motions;
  for (const RegionHandle<D>& region : regions_) motions.push_back(region.motion);
  return move_handles(std::move(to), motions, control);
}

template <int D>
EditResult EditSession<D>::move_handles(std::vector<Vec<D>> to, const std::vector<RegionMotion<D>>& motions,
                                        const WorkControl& control) {
  if (to.size() != handles_.size())
    throw std::invalid_argument("moving " + std::to_string(to.size()) + " handles, but the session has " +
                                std::to_string(handles_.size()));
  if (motions.size() != regions_.size())
    throw std::invalid_argument("moving " + std::to_string(motions.size()) + " regions, but the session has " +
                                std::to_string(regions_.size()));
  std::vector<RegionHandle<D>> regions_to = regions_;
  for (std::size_t r = 0; r < motions.size(); ++r) {
    if (regions_[r].pinned && !(motions[r] == regions_[r].motion))
      throw std::invalid_argument("region " + std::to_string(r) + " is pinned and cannot move");
    regions_to[r].motion = motions[r];
  }
  EditResult result;
  if (to == handles_ && same_places(regions_to, regions_)) return result;
  const MlsDeformation<D> deformation(handles_, to, regions_, regions_to, settings_.kind, settings_.alpha);
  if (points().empty()) {
    handles_ = std::move(to);
    regions_ = std::move(regions_to);
    result.changed = true;
    return result;
  }
  if (resamples_locally()) return move_handles_locally(deformation, std::move(to), std::move(regions_to), control);
  // As `amls deform`, where the policy decides before step k whether to
  // resample and once more after the last step: here the decision for the
  // points a step made is taken right after it (the step that follows, if
  // any, is k + 1), so the surface shown is the one a replay ends with. The
  // points are settled first unless the policy saw them already (the loaded
  // shape: step 0 always resamples).
  synced_surface();
  const bool resample = settings_.resample;
  const bool settle_first = resample && !settled_;
  const ResamplePolicy& policy = settings_.policy;
  const std::size_t k = recording_.steps().size();
  // The phases of settling the points before step `step`: measuring them (`auto`, after step 0), resampling.
  auto settle_phases = [&](std::size_t step) { return (policy_measures(policy, step) ? 1 : 0) + 1; };
  Phases phases(control, (settle_first ? settle_phases(k) : 0) + 1 + (resample ? settle_phases(k + 1) : 0));
  // Settles the points before step `step`; false if the edit must stop.
  // The regions where the points are (before the step, or after it, as a replay has them).
  auto settle_points = [&](std::size_t step, const std::vector<RegionHandle<D>>& regions, bool& resampled) {
    const std::optional<Settling> settled = settle(
        *surface_, policy, step, [&](const char* phase) { return phases.next(phase); }, held_regions(regions));
    if (!settled) return false;
    resampled = settled->resampled;
    if (resampled) {
      add_stats(result, settled->stats);
      ++result.resamples;
    }
    return true;
  };
  bool resampled_first = false;
  bool resampled_after = false;
  PointSet<D> before = surface_->points();
  const bool finished = phases.run(surface_->pool(), [&] {
    // Before step k a replay holds the regions where step k - 1 left them, and none before step 0.
    if (settle_first &&
        !settle_points(k, k == 0 ? std::vector<RegionHandle<D>>{} : recording_.steps()[k - 1].regions_to,
                       resampled_first))
      return false;
    if (!phases.next("deforming")) return false;
    add_stats(result, surface_->step(deformation, 0.0, 1.0, false));
    return !resample || settle_points(k + 1, regions_to, resampled_after);
  });
  if (!finished) {
    if (phases.started()) roll_back(std::move(before));
    result = EditResult{};
    result.cancelled = true;
    return result;
  }
  if (resampled_first) recording_.resampled(settings_);
  recording_.deformed(handles_, to, settings_, regions_, regions_to);
  if (resampled_after) recording_.resampled(settings_);
  handles_ = std::move(to);
  regions_ = std::move(regions_to);
  settled_ = resample;
  ++version_;
  result.changed = result.stepped = true;
  return result;
}

template <int D>
LocalDeformingSurface<D>& EditSession<D>::local_loop() {
  if (!local_)
    local_ = std::make_unique<LocalDeformingSurface<D>>(surface_->grid(), settings_.parameters(),
                                                        settings_.variant, threads_);
  return *local_;
}

template <int D>
void EditSession<D>::start_local(EditResult& result) {
  // Untouched points go in as loaded, as `amls deform` hands them over (see set_grid).
  const bool start = recording_.untouched();
  local_->set_points(start ? initial_.points : surface_->points());
  // The shape's own samples get the start's resample, as `amls deform` gives them.
  const LocalStepStats all = start ? local_->resample_start() : local_->resample_all();
  add_stats(result, StepStats{all.timings, all.resample.normals, all.resample.resample, all.points_before,
                              all.points_after, {}});
  ++result.resamples;
}

template <int D>
EditResult EditSession<D>::prepare_local(const WorkControl& control) {
  EditResult result;
  if (!resamples_locally() || local_in_sync() || points().empty()) return result;
  Phases phases(control, 1);
  const bool finished = phases.run(local_loop().pool(), [&] {
    if (!phases.next(kResamplingPhase)) return false;
    start_local(result);
    return true;
  });
  if (!finished) {
    local_version_ = ~std::uint64_t{0};  // the next step starts from the surface's points
    result = EditResult{};
    result.cancelled = true;
    return result;
  }
  recording_.resampled(settings_);
  settled_ = true;
  ++version_;
  local_version_ = version_;
  surface_behind_ = true;
  result.changed = true;
  return result;
}

template <int D>
EditResult EditSession<D>::move_handles_locally(const MlsDeformation<D>& deformation, std::vector<Vec<D>> to,
                                                std::vector<RegionHandle<D>> regions_to, const WorkControl& control) {
  // As `amls deform --resample local`: the points are resampled whole once
  // (the loaded shape, or points whose strain the loop does not know: after
  // resampling was off, or another policy), then each step maps them and
  // resamples where strained.
  local_loop();
  const bool start = !local_in_sync();
  EditResult result;
  Phases phases(control, start ? 2 : 1);
  // A stopped step leaves the local loop as it was, with its strain: the next step runs as if it never had.
  typename LocalDeformingSurface<D>::Saved local_before = start ? typename LocalDeformingSurface<D>::Saved{} : local_->save();
  const bool finished = phases.run(local_->pool(), [&] {
    if (start) {
      if (!phases.next(kResamplingPhase)) return false;
      start_local(result);
    }
    if (!phases.next("deforming, resampling where strained")) return false;
    const LocalStepStats step = local_->step(deformation);
    add_stats(result, StepStats{step.timings, step.resample.normals, step.resample.resample, step.points_before,
                                step.points_after, {}});
    if (step.resample.flagged_cells > 0) ++result.resamples;
    return true;
  });
  // surface_ is only read here: a stopped step leaves it as it was.
  if (!finished) {
    if (start)
      local_version_ = ~std::uint64_t{0};  // not begun: the next step starts from the surface's points
    else
      local_->restore(std::move(local_before));
    result = EditResult{};
    result.cancelled = true;
    return result;
  }
  if (start) recording_.resampled(settings_);
  recording_.deformed(handles_, to, settings_, regions_, regions_to);
  surface_behind_ = true;
  handles_ = std::move(to);
  regions_ = std::move(regions_to);
  settled_ = true;
  ++version_;
  local_version_ = version_;
  result.changed = result.stepped = true;
  return result;
}

template <int D>
EditResult EditSession<D>::resample_now(const WorkControl& control) {
  EditResult result;
  result.changed = true;
  DeformingSurface<D>& surface = synced_surface();
  if (surface.points().empty()) return result;
  Phases phases(control, 1);
  PointSet<D> before = surface.points();
  const bool finished = phases.run(surface.pool(), [&] {
    if (!phases.next(kResamplingPhase)) return false;
    // The shape's own samples get the start's resample, as `amls deform` gives them.
    add_stats(result, recording_.untouched() ? surface.resample_start() : surface.resample_only());
    result.resamples = 1;
    return true;
  });
  if (!finished) {
    if (phases.started()) roll_back(std::move(before));
    result.cancelled = true;
    return result;
  }
  recording_.resampled(settings_);
  settled_ = true;
  ++version_;
  return result;
}

template <int D>
EditResult EditSession<D>::set_variant(Variant variant, const WorkControl& control) {
  if (variant == settings_.variant) return {};
  push_undo();
  settings_.variant = variant;
  synced_surface().set_variant(variant);
  local_.reset();
  return resample_now(control);
}

template <int D>
EditResult EditSession<D>::set_grid(double spacing, double radius_factor, const WorkControl& control) {
  SurfaceSettings next = settings_;
  next.spacing = spacing;
  next.radius_factor = radius_factor;
  if (next.same_grid(settings_)) return {};
  // A resample at h' gives about (h / h')^(D-1) times as many points: refuse what would swamp the machine.
  const double expected = static_cast<double>(points().size()) * std::pow(settings_.spacing / spacing, D - 1);
  if (expected > kMaxExpectedPoints)
    throw std::invalid_argument("h = " + std::to_string(spacing) + " would make about " +
                                std::to_string(static_cast<long long>(expected)) +
                                " points; choose a larger grid spacing");
  std::unique_ptr<DeformingSurface<D>> surface = make_surface(next);  // throws before anything changed
  push_undo();
  // Untouched points go in as loaded, the order `amls deform` hands them to its
  // surface in: the old surface keeps them sorted by its own cells, and another
  // order of the fits' sums changes the last bits of the resample.
  surface->set_points(recording_.untouched() ? initial_.points : synced_surface().points());
  surface_ = std::move(surface);
  local_.reset();
  settings_ = next;
  ++version_;
  return resample_now(control);
}

template <int D>
void EditSession<D>::set_deformation(MlsKind kind, double alpha) {
  SurfaceSettings next = settings_;
  next.kind = kind;
  next.alpha = alpha;
  validate(next);
  settings_ = next;
}

template <int D>
void EditSession<D>::set_resampling(bool enabled, const ResamplePolicy& policy) {
  SurfaceSettings next = settings_;
  next.resample = enabled;
  next.policy = policy;
  validate(next);
  settings_ = next;
}

template <int D>
bool EditSession<D>::undo() {
  if (undo_.empty()) return false;
  redo_.push_back(current_state());
  restore(undo_.back());
  pop_undo(true);
  return true;
}

template <int D>
bool EditSession<D>::redo() {
  if (redo_.empty()) return false;
  State now = current_state();
  restore(redo_.back());
  redo_.pop_back();
  push_back_undo(std::move(now));
  return true;
}

template <int D>
void EditSession<D>::reset() {
  push_undo();
  State start = initial_;
  start.settings = settings_;
  start.recording = initial_.recording.restarted(settings_);
  restore(start);
}

template class EditSession<2>;
template class EditSession<3>;

}  // namespace amls::editor
