#pragma once
// Region handles between the editor's UI (3D terms: command::RegionMove,
// RegionView) and its session of dimension D (RegionMotion<D>). No GL.
#include <vector>

#include "app/editor/command.hpp"
#include "core/deform/region_handle.hpp"

namespace amls::editor {

// A region as the UI shows and edits it.
struct RegionView {
  std::vector<Vec<3>> members;  // where the region is now (2D: z = 0)
  Vec<3> centre = Vec<3>::Zero();       // the members' mean where the region is now: its marker
  Vec<3> rest_centre = Vec<3>::Zero();  // the same at rest (the motions' pivot)
  command::RegionMove motion;
  bool pinned = false;
};

template <int D>
RegionMotion<D> motion_from(const command::RegionMove& move) {
  RegionMotion<D> motion;
  motion.translation = move.translation.head<D>();
  if constexpr (D == 2)
    motion.rotation[0] = move.rotation.z();
  else
    motion.rotation = move.rotation;
  motion.scale = move.scale;
  return motion;
}

template <int D>
command::RegionMove move_of(const RegionMotion<D>& motion) {
  command::RegionMove move;
  move.translation.head<D>() = motion.translation;
  if constexpr (D == 2)
    move.rotation.z() = motion.rotation[0];
  else
    move.rotation = motion.rotation;
  move.scale = motion.scale;
  return move;
}

template <int D>
RegionView view_of(const RegionHandle<D>& handle) {
  RegionView view;
  for (const Vec<D>& m : handle.placed_members()) {
    view.members.push_back(Vec<3>::Zero());
    view.members.back().head<D>() = m;
  }
  view.rest_centre.head<D>() = handle.region->centre();
  view.centre.head<D>() = handle.place(handle.region->centre());
  view.motion = move_of<D>(handle.motion);
  view.pinned = handle.pinned;
  return view;
}

}  // namespace amls::editor
