#pragma once
// What the editor's UI asks its worker to do (editor_worker.hpp). Positions are
// 3D (z = 0 in 2D). No GL.
#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include "app/editor/surface_settings.hpp"

namespace amls::editor {

namespace command {

struct LoadFile {  // a point-set file or a scene
  std::string path;
  bool estimate_normals = false;  // a point set's own normals set aside and estimated (load_shape_file)
};
struct LoadShape {  // a built-in shape (circle in 2D, sphere in 3D)
  int dimension = 2;
  double radius = 1.0;
  std::size_t points = 250;
  double spacing = 0.024;
};
struct AddHandle {
  Vec<3> position = Vec<3>::Zero();
};
struct RemoveHandle {
  std::size_t index = 0;
};
struct BeginDrag {};  // the state now is what Esc and undo go back to
// A region handle's motion (core/geometry/region_motion.hpp) in 3D terms: in
// 2D the translation's z and the rotation vector's x and y are 0.
struct RegionMove {
  Vec<3> translation = Vec<3>::Zero();
  Vec<3> rotation = Vec<3>::Zero();
  double scale = 1.0;
};
struct MoveHandles {  // every handle's new position; coalesced: the newest wins
  std::vector<Vec<3>> positions;
  // Every region's motion; empty: the regions stay where they are.
  std::vector<RegionMove> regions;
};
struct AddRegion {  // a region of these members (where the surface is now), pinned or not
  std::vector<Vec<3>> members;
  bool pinned = false;
};
struct ReplaceRegion {  // region `index` gets these members (where the surface is now) and starts at rest
  std::size_t index = 0;
  std::vector<Vec<3>> members;
};
struct RemoveRegion {
  std::size_t index = 0;
};
struct PinRegion {
  std::size_t index = 0;
  bool pinned = true;
};
struct CancelDrag {};  // back to the state at BeginDrag
struct SetVariant {
  Variant variant = Variant::exact;
};
struct SetGrid {
  double spacing = 0.024;
  double radius_factor = 3.0;
};
struct SetDeformation {
  MlsKind kind = MlsKind::rigid;
  double alpha = 1.0;
};
struct SetResampling {
  bool enabled = true;
  ResamplePolicy policy;
};
struct SetCurveTracing {  // 2D: trace the MLS curve for display
  bool enabled = true;
};
struct Undo {};
struct Redo {};
struct Reset {};
struct Export {  // the current point set: PLY (with normals) or XYZ by the extension
  std::string path;
};
struct ExportMesh {  // the current surface as a mesh: OBJ or PLY by the extension (2D: a polyline)
  std::string path;
};
struct SaveScene {
  std::string path;
};

}  // namespace command

using Command =
    std::variant<command::LoadFile, command::LoadShape, command::AddHandle, command::RemoveHandle, command::BeginDrag,
                 command::MoveHandles, command::AddRegion, command::ReplaceRegion, command::RemoveRegion,
                 command::PinRegion, command::CancelDrag, command::SetVariant, command::SetGrid,
                 command::SetDeformation, command::SetResampling, command::SetCurveTracing, command::Undo,
                 command::Redo, command::Reset, command::Export, command::ExportMesh, command::SaveScene>;

// LoadFile or LoadShape: the commands that replace the session.
bool is_load(const Command& command);
// A load or a parameter change stops the step that is running (between its
// phases or inside one), and so do Esc, undo, redo and reset. A load that is
// running is stopped only by another load or Esc: a setting changed while a
// scan opens applies to the opened surface (it came after the load), and
// cancelling the load would throw the file away instead.
bool cancels_running_work(const Command& command, bool running_is_load);
// Loads, Esc, undo, redo and reset make the handle moves still queued before
// them pointless: those are dropped.
bool supersedes_queued_moves(const Command& command);
// For the status line: "loading", "moving handles", ...
const char* describe(const Command& command);

}  // namespace amls::editor
