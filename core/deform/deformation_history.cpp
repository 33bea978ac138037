#include "core/deform/deformation_history.hpp"

#include <cmath>
#include <stdexcept>

namespace amls {

namespace {

std::string stage_name(std::size_t i) { return "stages[" + std::to_string(i) + "]"; }

}  // namespace

template <int D>
std::size_t HandleStage<D>::steps() const {
  std::size_t total = 0;
  for (const HandleTarget<D>& target : targets) total += target.steps;
  return total;
}

template <int D>
std::vector<Vec<D>> HandleStage<D>::handles_after(std::size_t k) const {
  if (k == 0) return start;
  const std::vector<Vec<D>>* previous = &start;
  std::size_t done = 0;
  for (const HandleTarget<D>& target : targets) {
    if (k <= done + target.steps) {
      if (target.handles.size() != previous->size())
        throw std::invalid_argument("a target has " + std::to_string(target.handles.size()) +
                                    " handles, but its stage has " + std::to_string(previous->size()));
      // (1 - t) a + t b is exact at t = 1, so each target is reached exactly.
      const double t = static_cast<double>(k - done) / static_cast<double>(target.steps);
      std::vector<Vec<D>> out(previous->size());
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = (1.0 - t) * (*previous)[i] + t * target.handles[i];
      return out;
    }
    done += target.steps;
    previous = &target.handles;
  }
  throw std::out_of_range("step " + std::to_string(k) + " is past the stage's " + std::to_string(done) + " steps");
}

template <int D>
std::vector<RegionHandle<D>> HandleStage<D>::regions_after(std::size_t k) const {
  std::vector<RegionHandle<D>> out = regions;
  if (k == 0) return out;
  std::size_t done = 0;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const HandleTarget<D>& target = targets[t];
    if (k <= done + target.steps) {
      if (target.regions.size() != regions.size())
        throw std::invalid_argument("a target has " + std::to_string(target.regions.size()) +
                                    " region motions, but its stage has " + std::to_string(regions.size()) + " regions");
      const double s = static_cast<double>(k - done) / static_cast<double>(target.steps);
      for (std::size_t r = 0; r < out.size(); ++r)
        out[r].motion = RegionMotion<D>::lerp(t == 0 ? regions[r].motion : targets[t - 1].regions[r], target.regions[r], s);
      return out;
    }
    done += target.steps;
  }
  throw std::out_of_range("step " + std::to_string(k) + " is past the stage's " + std::to_string(done) + " steps");
}

template <int D>
void DeformationHistory<D>::begin_stage(std::vector<Vec<D>> start, std::vector<RegionHandle<D>> regions) {
  stages.push_back(HandleStage<D>{std::move(start), {}, std::move(regions)});
}

template <int D>
void DeformationHistory<D>::add_target(std::vector<Vec<D>> handles, std::size_t steps,
                                       std::vector<RegionMotion<D>> regions) {
  if (stages.empty()) throw std::invalid_argument("a target needs a stage: call begin_stage first");
  HandleStage<D>& stage = stages.back();
  if (handles.size() != stage.start.size())
    throw std::invalid_argument("the target has " + std::to_string(handles.size()) + " handles, but the stage has " +
                                std::to_string(stage.start.size()) +
                                " (adding or removing a handle starts a new stage)");
  if (regions.size() != stage.regions.size())
    throw std::invalid_argument("the target has " + std::to_string(regions.size()) + " region motions, but the stage has " +
                                std::to_string(stage.regions.size()) +
                                " regions (adding or removing a region starts a new stage)");
  if (steps == 0) throw std::invalid_argument("a target needs at least one step");
  stage.targets.push_back(HandleTarget<D>{std::move(handles), steps, std::move(regions)});
}

template <int D>
std::size_t DeformationHistory<D>::total_steps() const {
  std::size_t total = 0;
  for (const HandleStage<D>& stage : stages) total += stage.steps();
  return total;
}

template <int D>
void DeformationHistory<D>::validate() const {
  auto check_finite = [](const std::vector<Vec<D>>& handles, const std::string& where) {
    for (std::size_t h = 0; h < handles.size(); ++h)
      for (int a = 0; a < D; ++a)
        if (!std::isfinite(handles[h][a]))
          throw std::invalid_argument(where + "[" + std::to_string(h) + "][" + std::to_string(a) +
                                      "]: not a finite number");
  };
  auto check_motion = [](const RegionMotion<D>& motion, const std::string& where) {
    if (!motion.finite()) throw std::invalid_argument(where + ": not a finite motion");
    if (!(motion.scale > 0.0)) throw std::invalid_argument(where + ".scale: must be positive");
  };
  if (stages.empty()) throw std::invalid_argument("stages: the history has no stage");
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const HandleStage<D>& stage = stages[s];
    if (stage.start.empty() && stage.regions.empty())
      throw std::invalid_argument(stage_name(s) + ".handles: a stage needs at least one handle or region");
    check_finite(stage.start, stage_name(s) + ".handles");
    for (std::size_t r = 0; r < stage.regions.size(); ++r) {
      const std::string where = stage_name(s) + ".regions[" + std::to_string(r) + "]";
      if (!stage.regions[r].region) throw std::invalid_argument(where + ": no region");
      check_motion(stage.regions[r].motion, where);
    }
    if (stage.targets.empty())
      throw std::invalid_argument(stage_name(s) + ".targets: a stage needs at least one target");
    for (std::size_t t = 0; t < stage.targets.size(); ++t) {
      const HandleTarget<D>& target = stage.targets[t];
      const std::string where = stage_name(s) + ".targets[" + std::to_string(t) + "]";
      if (target.handles.size() != stage.start.size())
        throw std::invalid_argument(where + ".handles: " + std::to_string(target.handles.size()) +
                                    " handles, but the stage has " + std::to_string(stage.start.size()) +
                                    " (adding or removing a handle starts a new stage)");
      check_finite(target.handles, where + ".handles");
      if (target.steps == 0) throw std::invalid_argument(where + ".steps: must be at least 1");
      if (target.regions.size() != stage.regions.size())
        throw std::invalid_argument(where + ".regions: " + std::to_string(target.regions.size()) +
                                    " motions, but the stage has " + std::to_string(stage.regions.size()) +
                                    " regions (adding or removing a region starts a new stage)");
      for (std::size_t r = 0; r < target.regions.size(); ++r) {
        const std::string at = where + ".regions[" + std::to_string(r) + "]";
        check_motion(target.regions[r], at);
        if (stage.regions[r].pinned && !(target.regions[r] == stage.regions[r].motion))
          throw std::invalid_argument(at + ": the region is pinned in this stage, but the target moves it");
      }
    }
  }
}

template <int D>
HistoryStep<D> DeformationHistory<D>::step(std::size_t stage, std::size_t step_in_stage) const {
  if (stage >= stages.size())
    throw std::out_of_range("stage " + std::to_string(stage) + " does not exist (the history has " +
                            std::to_string(stages.size()) + ")");
  const HandleStage<D>& s = stages[stage];
  if (step_in_stage >= s.steps())
    throw std::out_of_range("step " + std::to_string(step_in_stage) + " does not exist in stage " +
                            std::to_string(stage) + " (it has " + std::to_string(s.steps()) + ")");
  HistoryStep<D> out;
  out.stage = stage;
  out.step_in_stage = step_in_stage;
  for (std::size_t i = 0; i < stage; ++i) out.index += stages[i].steps();
  out.index += step_in_stage;
  out.from = s.handles_after(step_in_stage);
  out.to = s.handles_after(step_in_stage + 1);
  out.regions_from = s.regions_after(step_in_stage);
  out.regions_to = s.regions_after(step_in_stage + 1);
  return out;
}

template <int D>
HistoryStep<D> DeformationHistory<D>::step(std::size_t index) const {
  std::size_t k = index;
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const std::size_t n = stages[s].steps();
    if (k < n) return step(s, k);
    k -= n;
  }
  throw std::out_of_range("step " + std::to_string(index) + " does not exist (the history has " +
                          std::to_string(total_steps()) + ")");
}

template <int D>
HistoryStep<D> DeformationHistory<D>::Iterator::operator*() const {
  return history_->step(stage_, step_);
}

template <int D>
typename DeformationHistory<D>::Iterator& DeformationHistory<D>::Iterator::operator++() {
  ++index_;
  ++step_;
  // Skip to the next stage with steps (a stage of zero steps only exists before validate()).
  while (stage_ < history_->stages.size() && step_ >= history_->stages[stage_].steps()) {
    ++stage_;
    step_ = 0;
  }
  return *this;
}

template <int D>
typename DeformationHistory<D>::Iterator DeformationHistory<D>::StepRange::begin() const {
  std::size_t stage = 0;
  while (stage < history->stages.size() && history->stages[stage].steps() == 0) ++stage;
  return Iterator(history, stage, 0, 0);
}

template struct HandleStage<2>;
template struct HandleStage<3>;
template struct DeformationHistory<2>;
template struct DeformationHistory<3>;

}  // namespace amls
