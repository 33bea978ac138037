#include "core/util/file_error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace amls {

void throw_cannot_open(const std::string& path, const std::string& doing) {
  const int error = errno;  // before anything else can change it
  throw FileError(path + ": " + doing + ": " + std::strerror(error), error);
}

void reject_directory(const std::string& path, const std::string& what) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw FileError(path + ": is a directory, not a " + what, EISDIR);
}

}  // namespace amls
