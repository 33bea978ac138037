#pragma once
// A file the system would not open, create, write or replace - as opposed to
// one whose contents are wrong, which the readers report as std::runtime_error
// naming the line. Callers that map errors onto other kinds (the Python
// module's OSError subclasses: FileNotFoundError, IsADirectoryError,
// PermissionError) tell the two apart by this type and its errno value.
#include <stdexcept>
#include <string>

namespace amls {

class FileError : public std::runtime_error {
 public:
  // `error`: the errno value the system gave (ENOENT, EISDIR, EACCES, ...), 0 if none.
  FileError(const std::string& message, int error) : std::runtime_error(message), error_(error) {}
  int error() const { return error_; }

 private:
  int error_;
};

// Throws FileError "PATH: DOING: <the system's words for errno>" with errno's
// value: for a file whose opening just failed.
[[noreturn]] void throw_cannot_open(const std::string& path, const std::string& doing);

// Throws FileError (EISDIR) "PATH: is a directory, not a WHAT" when `path` is a directory.
void reject_directory(const std::string& path, const std::string& what);

}  // namespace amls
