#pragma once
// What a selection does to the editor's region handles, as the worker
// command that does it: a finished lasso or brush stroke makes a new region,
// adds to the active one or takes from it; Invert and Clear change the active
// region. Pure: no UI state, no GL; RegionTool posts the commands.
#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "app/editor/command.hpp"
#include "app/editor/region_moves.hpp"

namespace amls::editor {

enum class SelectionEdit { new_region, add, subtract };

// The command that applies a finished selection to `regions`, of which
// `active` is the active one (if any):
// - new_region, or no active region: the `selected` positions become a new,
//   moving region (AddRegion);
// - add: they join the active region's members (ReplaceRegion);
// - subtract: the active region's members for which `taken` holds go
//   (ReplaceRegion), and with them the region if none is left (RemoveRegion).
// Nothing when the selection would change nothing: nothing selected to make
// or add, nothing taken.
std::optional<Command> selection_command(SelectionEdit edit, std::optional<std::size_t> active,
                                         std::span<const RegionView> regions, std::vector<Vec<3>> selected,
                                         const std::function<bool(const Vec<3>&)>& taken);

// Invert region `index`: the points of `positions` farther than `reach` from
// every member become its members. Nothing if there is no such region or no
// point lies that far. Throws std::invalid_argument for a reach that is not a
// finite number > 0.
std::optional<Command> inversion_command(std::span<const RegionView> regions, std::size_t index,
                                         std::span<const glm::vec3> positions, double reach);

// Clear the active region: it goes. Nothing if there is no such region.
std::optional<Command> clearing_command(std::span<const RegionView> regions, std::optional<std::size_t> active);

}  // namespace amls::editor
