#include "app/editor/directory_listing.hpp"

#include <algorithm>

#include "core/io/file_format.hpp"

namespace amls::editor {

bool is_openable_file(const std::filesystem::path& path) {
  return shape_file_format(path.string()).has_value() || lower_extension(path.string()) == ".json";
}

DirectoryListing list_directory(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  DirectoryListing listing;
  std::error_code error;
  listing.path = fs::absolute(folder, error).lexically_normal();
  if (listing.path.has_relative_path() && listing.path.filename().empty())
    listing.path = listing.path.parent_path();  // no trailing separator
  fs::directory_iterator it(listing.path, fs::directory_options::skip_permission_denied, error);
  if (error) {
    listing.error = listing.path.string() + ": " + error.message();
    return listing;
  }
  for (; it != fs::directory_iterator(); it.increment(error)) {
    if (error) break;
    const std::string name = it->path().filename().string();
    if (name.empty() || name.front() == '.') continue;
    std::error_code ignored;
    if (it->is_directory(ignored)) {
      listing.entries.push_back({name, true, 0});
    } else if (is_openable_file(it->path())) {
      listing.entries.push_back({name, false, it->file_size(ignored)});
    }
  }
  std::sort(listing.entries.begin(), listing.entries.end(), [](const DirectoryEntry& a, const DirectoryEntry& b) {
    if (a.is_directory != b.is_directory) return a.is_directory;
    return a.name < b.name;
  });
  return listing;
}

}  // namespace amls::editor
