#pragma once
// A small ImGui file browser: folders and the files the editor opens (.ply,
// .xyz, .json). Double-click a folder to enter it, a file to open it.
#include <filesystem>
#include <optional>
#include <string>

#include "app/editor/directory_listing.hpp"

namespace amls::editor {

class FileBrowser {
 public:
  explicit FileBrowser(std::filesystem::path folder);

  // Draws the browser while `open`, with the choice of a point set's normals
  // (its own, or set aside and estimated); returns a file the user chose (and closes).
  std::optional<std::string> draw(bool& open, bool& estimate_normals);

 private:
  void enter(const std::filesystem::path& folder);

  DirectoryListing listing_;
  std::string typed_;  // the path field
  int selected_ = -1;
};

}  // namespace amls::editor
