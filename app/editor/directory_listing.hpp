#pragma once
// What the editor's file browser shows of a folder: its sub-folders, then the
// files the editor opens (point sets: .ply, .off, .xyz, .pwn, .csv, .txt; scenes:
// .json), each group sorted by name;
// hidden entries left out. No GL.
#include <filesystem>
#include <string>
#include <vector>

namespace amls::editor {

struct DirectoryEntry {
  std::string name;
  bool is_directory = false;
  std::uintmax_t size = 0;  // bytes, files only
};

struct DirectoryListing {
  std::filesystem::path path;  // absolute, normalised
  std::vector<DirectoryEntry> entries;
  std::string error;  // why the folder could not be read (entries empty)
};

// Whether the editor opens files with this name's extension (any case).
bool is_openable_file(const std::filesystem::path& path);

DirectoryListing list_directory(const std::filesystem::path& folder);

}  // namespace amls::editor
