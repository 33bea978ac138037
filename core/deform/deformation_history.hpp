#pragma once
// A deformation history made of handle stages (paper, section 4, with the
// handle deformation of Schaefer et al.): the one format that scenes, the
// editor's Save Scene and `amls deform` share.
//
// A stage has a fixed set of handles: their positions at the stage's start and
// a sequence of target configurations, each reached in a given number of steps.
// Between consecutive configurations the handles move linearly; step k of a
// stage maps points by the MLS deformation that takes the handles at step k to
// the handles at step k + 1 (the paper's phi_{m tau -> (m+1) tau}), and the
// surface is resampled between steps. Adding or removing a handle starts a new
// stage, whose start positions are free (a handle that stays usually starts
// where the previous stage left it).
//
// A stage may also hold region handles (region_handle.hpp): each starts at a
// motion of its own, and every target gives each region the motion it
// reaches, as it gives each point handle its position; the motions'
// parameters move linearly in between. A pinned region keeps its start
// motion in every target. Adding or removing a region, or changing its
// members, starts a new stage as a handle does.
#include <cstddef>
#include <string>
#include <vector>

#include "core/deform/region_handle.hpp"
#include "core/math/vec.hpp"

namespace amls {

template <int D>
struct HandleTarget {
  std::vector<Vec<D>> handles;  // the configuration reached, one position per handle of the stage
  std::size_t steps = 1;        // steps taken to reach it from the previous configuration (>= 1)
  std::vector<RegionMotion<D>> regions;  // the motion reached, one per region of the stage
};

template <int D>
struct HandleStage {
  std::vector<Vec<D>> start;  // handle positions at the stage's start
  std::vector<HandleTarget<D>> targets;
  std::vector<RegionHandle<D>> regions;  // the region handles at the stage's start

  std::size_t steps() const;
  // The handles after `k` steps of this stage: start at 0, the last target at steps().
  // Throws std::out_of_range past steps().
  std::vector<Vec<D>> handles_after(std::size_t k) const;
  // The same for the regions.
  std::vector<RegionHandle<D>> regions_after(std::size_t k) const;
};

// One step of a history: the handles before and after it.
template <int D>
struct HistoryStep {
  std::size_t index = 0;          // over the whole history, from 0
  std::size_t stage = 0;          // which stage
  std::size_t step_in_stage = 0;  // from 0 within the stage
  std::vector<Vec<D>> from;
  std::vector<Vec<D>> to;
  std::vector<RegionHandle<D>> regions_from;
  std::vector<RegionHandle<D>> regions_to;
};

template <int D>
struct DeformationHistory {
  std::vector<HandleStage<D>> stages;

  // Building, as an editor records it: a new stage (a handle was added or
  // removed), then targets for it. add_target throws std::invalid_argument if
  // there is no stage yet, the handle or region count differs from the
  // stage's, or steps is 0.
  void begin_stage(std::vector<Vec<D>> start, std::vector<RegionHandle<D>> regions = {});
  void add_target(std::vector<Vec<D>> handles, std::size_t steps, std::vector<RegionMotion<D>> regions = {});

  std::size_t total_steps() const;

  // Throws std::invalid_argument naming the first fault by its place in the
  // scene format (`stages[1].targets[0].handles: ...`): a stage without
  // handles (of either kind) or targets, a target whose handle or region count
  // differs from its stage's, zero steps, a non-finite coordinate or motion, a
  // scale not > 0, a pinned region that moves.
  void validate() const;

  // (stage, step within it) -> (handles before, handles after). Throws
  // std::out_of_range for a stage or step that does not exist.
  HistoryStep<D> step(std::size_t stage, std::size_t step_in_stage) const;
  // The same by index over the whole history, 0 <= index < total_steps().
  HistoryStep<D> step(std::size_t index) const;

  // Walks the steps in order: for (const HistoryStep<D>& s : history.steps()).
  class Iterator {
   public:
    Iterator(const DeformationHistory* history, std::size_t stage, std::size_t step, std::size_t index)
        : history_(history), stage_(stage), step_(step), index_(index) {}
    HistoryStep<D> operator*() const;
    Iterator& operator++();
    bool operator==(const Iterator& other) const { return index_ == other.index_; }
    bool operator!=(const Iterator& other) const { return index_ != other.index_; }

   private:
    const DeformationHistory* history_;
    std::size_t stage_, step_, index_;
  };
  struct StepRange {
    const DeformationHistory* history;
    Iterator begin() const;
    Iterator end() const { return Iterator(history, 0, 0, history->total_steps()); }
  };
  StepRange steps() const { return StepRange{this}; }
};

extern template struct HandleStage<2>;
extern template struct HandleStage<3>;
extern template struct DeformationHistory<2>;
extern template struct DeformationHistory<3>;

}  // namespace amls
