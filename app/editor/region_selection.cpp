#include "app/editor/region_selection.hpp"

#include <algorithm>
#include <utility>

#include "core/geometry/point_region.hpp"

namespace amls::editor {

std::optional<Command> selection_command(SelectionEdit edit, std::optional<std::size_t> active,
                                         std::span<const RegionView> regions, std::vector<Vec<3>> selected,
                                         const std::function<bool(const Vec<3>&)>& taken) {
  const bool on_active = active && *active < regions.size() && edit != SelectionEdit::new_region;
  if (!on_active) {
    if (selected.empty()) return std::nullopt;
    return command::AddRegion{std::move(selected), false};
  }
  std::vector<Vec<3>> members = regions[*active].members;
  if (edit == SelectionEdit::add) {
    if (selected.empty()) return std::nullopt;
    members.insert(members.end(), selected.begin(), selected.end());
    return command::ReplaceRegion{*active, std::move(members)};
  }
  if (std::erase_if(members, taken) == 0) return std::nullopt;
  if (members.empty()) return command::RemoveRegion{*active};
  return command::ReplaceRegion{*active, std::move(members)};
}

std::optional<Command> inversion_command(std::span<const RegionView> regions, std::size_t index,
                                         std::span<const glm::vec3> positions, double reach) {
  if (index >= regions.size() || regions[index].members.empty()) return std::nullopt;
  const PointRegion<3> region(regions[index].members, reach);
  std::vector<Vec<3>> outside;
  for (const glm::vec3& p : positions) {
    const Vec<3> x(p.x, p.y, p.z);
    if (!region.contains(x)) outside.push_back(x);
  }
  if (outside.empty()) return std::nullopt;
  return command::ReplaceRegion{index, std::move(outside)};
}

std::optional<Command> clearing_command(std::span<const RegionView> regions, std::optional<std::size_t> active) {
  if (!active || *active >= regions.size()) return std::nullopt;
  return command::RemoveRegion{*active};
}

}  // namespace amls::editor
