#include "core/util/staged_directory.hpp"

#include <filesystem>
#include <stdexcept>

#include "core/util/file_error.hpp"

namespace amls {

namespace {

namespace fs = std::filesystem;

// A directory that may be replaced: absent, empty, or an earlier complete output.
void check_replaceable(const fs::path& path, const std::string& marker) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status))
    throw std::runtime_error(path.string() + ": exists and is not a directory; choose another output directory");
  if (fs::is_empty(path, error) || fs::is_regular_file(path / marker, error)) return;
  throw std::runtime_error(path.string() + ": exists and is not an earlier output (it has no " + marker +
                           "); choose another output directory or remove it");
}

}  // namespace

StagedDirectory::StagedDirectory(std::string path, std::string marker)
    : path_(std::move(path)), marker_(std::move(marker)) {
  while (!path_.empty() && path_.size() > 1 && path_.back() == '/') path_.pop_back();
  if (path_.empty()) throw std::runtime_error("the output directory's name is empty");
  check_replaceable(path_, marker_);
  staging_ = path_ + ".partial";
  std::error_code error;
  fs::remove_all(staging_, error);
  if (error) throw std::runtime_error(staging_ + ": cannot remove what an earlier run left: " + error.message());
  fs::create_directories(staging_, error);
  if (error) throw FileError(staging_ + ": cannot create the directory: " + error.message(), error.value());
}

std::string StagedDirectory::file(const std::string& name) const { return (fs::path(staging_) / name).string(); }

void StagedDirectory::commit() {
  std::error_code error;
  if (!fs::is_regular_file(fs::path(staging_) / marker_, error))
    throw std::runtime_error(staging_ + ": not committed, since " + marker_ + " was not written");
  check_replaceable(path_, marker_);
  // Move an earlier output aside first, so that a failed rename loses nothing.
  const fs::path old = path_ + ".old";
  fs::remove_all(old, error);
  const bool had_old = fs::exists(path_, error);
  if (had_old) {
    fs::rename(path_, old, error);
    if (error) throw std::runtime_error(path_ + ": cannot move the earlier output aside: " + error.message());
  }
  fs::rename(staging_, path_, error);
  if (error) {
    std::error_code ignored;
    if (had_old) fs::rename(old, path_, ignored);
    throw std::runtime_error(path_ + ": cannot rename " + staging_ + " into place: " + error.message());
  }
  if (had_old) fs::remove_all(old, error);
  committed_ = true;
}

}  // namespace amls
