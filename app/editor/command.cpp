#include "app/editor/command.hpp"

#include "app/editor/overloaded.hpp"

namespace amls::editor {

namespace {

template <typename... Ts>
bool holds_one_of(const Command& command) {
  return (std::holds_alternative<Ts>(command) || ...);
}

}  // namespace

bool is_load(const Command& c) {
  using namespace command;
  return holds_one_of<LoadFile, LoadShape>(c);
}

bool cancels_running_work(const Command& c, bool running_is_load) {
  using namespace command;
  if (running_is_load) return holds_one_of<LoadFile, LoadShape, CancelDrag>(c);
  return holds_one_of<LoadFile, LoadShape, SetVariant, SetGrid, SetDeformation, SetResampling, CancelDrag, Undo, Redo,
                      Reset>(c);
}

bool supersedes_queued_moves(const Command& c) {
  using namespace command;
  return holds_one_of<LoadFile, LoadShape, CancelDrag, Undo, Redo, Reset>(c);
}

const char* describe(const Command& c) {
  using namespace command;
  return std::visit(
      Overloaded{
          [](const LoadFile&) { return "loading"; }, [](const LoadShape&) { return "loading"; },
          [](const AddHandle&) { return "adding a handle"; }, [](const RemoveHandle&) { return "removing a handle"; },
          [](const BeginDrag&) { return "starting a drag"; }, [](const MoveHandles&) { return "deforming"; },
          [](const AddRegion&) { return "adding a region"; }, [](const ReplaceRegion&) { return "changing a region"; },
          [](const RemoveRegion&) { return "removing a region"; }, [](const PinRegion&) { return "pinning a region"; },
          [](const CancelDrag&) { return "cancelling the drag"; },
          [](const SetVariant&) { return "changing the variant"; }, [](const SetGrid&) { return "changing the grid"; },
          [](const SetDeformation&) { return "changing the MLS map"; },
          [](const SetResampling&) { return "switching resampling"; },
          [](const SetCurveTracing&) { return "switching the curve"; }, [](const Undo&) { return "undoing"; },
          [](const Redo&) { return "redoing"; }, [](const Reset&) { return "resetting"; },
          [](const Export&) { return "exporting"; }, [](const ExportMesh&) { return "exporting the mesh"; },
          [](const SaveScene&) { return "saving the scene"; }},
      c);
}

}  // namespace amls::editor
