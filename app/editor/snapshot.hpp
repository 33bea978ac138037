#pragma once
// What the editor's worker hands to the UI: immutable snapshots of the
// session, its progress while it works, and messages for the status line. No GL
// (render/point_data.hpp is the renderer's CPU side).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/editor/region_moves.hpp"
#include "app/editor/surface_settings.hpp"
#include "core/surface/curve_tracing.hpp"
#include "core/run/deforming_surface.hpp"
#include "core/surface/metrics.hpp"
#include "render/point_data.hpp"

namespace amls::editor {

// Each point's nearest-neighbour distance / h, in the points' order and ready
// to draw with them (the colours of `Snapshot::points`).
struct SpacingPerPoint {
  std::vector<double> values;
  PreparedScalars drawn;
};

struct Snapshot {
  std::uint64_t generation = 0;      // increases with every snapshot
  std::uint64_t processed = 0;       // the sequence number of the last command applied
  std::uint64_t load_id = 0;         // changes when a new shape is loaded (the view refits)
  std::uint64_t points_version = 0;  // changes when the point set does (the UI uploads it again)
  int dimension = 0;                 // 0: nothing loaded yet
  std::string name;

  // The points ready to draw (float positions and unit normals, 2D: z = 0, the
  // bounds, the undrawable ones left out): made once per point set on the
  // worker's pool and shared by the snapshots of that set, so that the UI
  // thread only uploads them and picks on them. Never null.
  std::shared_ptr<const PreparedPoints> points = std::make_shared<const PreparedPoints>();
  // Each point's nearest-neighbour distance / h and their statistics, measured
  // on the points of `spacing_version`: while a drag runs, the spacing is
  // measured only when the worker waits for commands (it costs more than a
  // local step on a million points), and a snapshot carries the last
  // measurement, shared, while the point count stays (null when it changed).
  std::shared_ptr<const SpacingPerPoint> spacing_h;
  SpacingStats spacing;
  static constexpr std::uint64_t kNotMeasured = ~std::uint64_t{0};
  std::uint64_t spacing_version = kNotMeasured;
  std::vector<Vec<3>> handles;      // 2D: z = 0
  std::vector<RegionView> regions;  // the region handles
  std::vector<CurveSegment> curve;  // 2D: the MLS curve F = 0, when traced
  SurfaceSettings settings;
  Vec<3> grid_origin = Vec<3>::Zero();

  // The paper's Table 1, live: the last step's phases and the totals since the load.
  bool has_last = false;
  StepStats last;
  PhaseTimings total;
  std::size_t steps = 0;          // deformation steps since the load
  std::size_t resamples = 0;      // resamples since the load (steps, variant and grid changes)
  std::size_t cancelled = 0;      // edits stopped (between or inside phases) since the worker started
  double steps_per_second = 0.0;  // over the last second of steps

  bool can_undo = false;
  bool can_redo = false;
  std::size_t recorded_steps = 0;  // what Save Scene would write
  std::string replay_note;         // empty if `amls deform` replays the session exactly
  std::string replay_arguments;    // what that replay needs on its command line ("--resample auto", ...)
};

// The worker at this moment.
struct WorkerStatus {
  bool busy = false;
  std::string activity;  // "deforming", "resampling", ...
  int phase = 0;         // of `phases`, from 0
  int phases = 0;
  double seconds = 0.0;  // since the running command started
  std::size_t queued = 0;
};

struct Message {
  enum class Level { info, warning, error };
  Level level = Level::info;
  std::string text;
};

}  // namespace amls::editor
