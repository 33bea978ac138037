// What a selection does to the editor's region handles (app/editor/region_selection.hpp):
// new, add, subtract, invert and clear, as the commands the region tool posts.
#include <doctest/doctest.h>

#include <optional>
#include <stdexcept>
#include <variant>
#include <vector>

#include "app/editor/region_selection.hpp"

using namespace amls;
using namespace amls::editor;

namespace {

// Points 0.1 apart along x.
std::vector<Vec<3>> row(int from, int to) {
  std::vector<Vec<3>> out;
  for (int i = from; i <= to; ++i) out.emplace_back(0.1 * i, 0.0, 0.0);
  return out;
}

std::vector<RegionView> regions_of(std::vector<std::vector<Vec<3>>> members) {
  std::vector<RegionView> out;
  for (std::vector<Vec<3>>& m : members) {
    RegionView view;
    view.members = std::move(m);
    out.push_back(std::move(view));
  }
  return out;
}

const auto nothing_taken = [](const Vec<3>&) { return false; };

// The command, which must be a T (a copy: the command given is often a temporary).
template <typename T>
T as(const std::optional<Command>& command) {
  REQUIRE(command);
  REQUIRE(std::holds_alternative<T>(*command));
  return std::get<T>(*command);
}

}  // namespace

TEST_CASE("region selection: a new selection makes a moving region of the points selected") {
  const std::vector<RegionView> regions = regions_of({row(0, 4)});
  for (const std::optional<std::size_t> active : {std::optional<std::size_t>(), std::optional<std::size_t>(0)}) {
    const auto add = as<command::AddRegion>(
        selection_command(SelectionEdit::new_region, active, regions, row(10, 12), nothing_taken));
    CHECK(add.members == row(10, 12));
    CHECK_FALSE(add.pinned);
  }
  // Nothing selected: nothing to make.
  CHECK_FALSE(selection_command(SelectionEdit::new_region, std::nullopt, regions, {}, nothing_taken));
}

TEST_CASE("region selection: add joins the points to the active region, or makes one when none is active") {
  const std::vector<RegionView> regions = regions_of({row(0, 4), row(20, 22)});
  const auto replaced =
      as<command::ReplaceRegion>(selection_command(SelectionEdit::add, 1, regions, row(30, 31), nothing_taken));
  CHECK(replaced.index == 1);
  std::vector<Vec<3>> expected = row(20, 22);
  for (const Vec<3>& p : row(30, 31)) expected.push_back(p);
  CHECK(replaced.members == expected);
  // No active region, or one that is gone: a new region.
  CHECK(as<command::AddRegion>(selection_command(SelectionEdit::add, std::nullopt, regions, row(30, 31), nothing_taken))
            .members == row(30, 31));
  CHECK(as<command::AddRegion>(selection_command(SelectionEdit::add, 5, regions, row(30, 31), nothing_taken)).members ==
        row(30, 31));
  CHECK_FALSE(selection_command(SelectionEdit::add, 1, regions, {}, nothing_taken));
}

TEST_CASE("region selection: subtract takes the members the selection covers, and the region when none is left") {
  const std::vector<RegionView> regions = regions_of({row(0, 9)});
  const auto right_half = [](const Vec<3>& m) { return m.x() > 0.45; };
  const auto replaced =
      as<command::ReplaceRegion>(selection_command(SelectionEdit::subtract, 0, regions, {}, right_half));
  CHECK(replaced.index == 0);
  CHECK(replaced.members == row(0, 4));
  CHECK(as<command::RemoveRegion>(selection_command(SelectionEdit::subtract, 0, regions, {}, [](const Vec<3>&) {
          return true;
        })).index == 0);
  // Nothing covered: nothing changes (no undo step).
  CHECK_FALSE(selection_command(SelectionEdit::subtract, 0, regions, row(0, 9), nothing_taken));
}

TEST_CASE("region selection: invert makes the points farther than the reach from the region its members") {
  const std::vector<RegionView> regions = regions_of({row(0, 2)});
  std::vector<glm::vec3> positions;
  for (int i = 0; i <= 9; ++i) positions.emplace_back(0.1f * static_cast<float>(i), 0.0f, 0.0f);
  const auto inverted = as<command::ReplaceRegion>(inversion_command(regions, 0, positions, 0.15));
  CHECK(inverted.index == 0);
  // Point 3 lies 0.1 from member 2: within reach. Points 4 to 9 do not.
  REQUIRE(inverted.members.size() == 6);
  for (std::size_t k = 0; k < 6; ++k)
    CHECK(inverted.members[k].x() == doctest::Approx(0.1 * static_cast<double>(k + 4)));
  // Every point within reach, or no such region: nothing to do.
  CHECK_FALSE(inversion_command(regions, 0, positions, 1.0));
  CHECK_FALSE(inversion_command(regions, 1, positions, 0.15));
  CHECK_THROWS_AS(inversion_command(regions, 0, positions, 0.0), std::invalid_argument);
}

TEST_CASE("region selection: clear removes the active region, and nothing when there is none") {
  const std::vector<RegionView> regions = regions_of({row(0, 2), row(5, 6)});
  CHECK(as<command::RemoveRegion>(clearing_command(regions, 1)).index == 1);
  CHECK_FALSE(clearing_command(regions, std::nullopt));
  CHECK_FALSE(clearing_command(regions, 2));
}
