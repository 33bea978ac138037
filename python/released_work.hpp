#pragma once
// Long work from Python: run with the GIL released, so that other Python
// threads go on, and stopped by Ctrl+C within a second.
//
// The work runs on a thread of its own while the calling thread, which is
// the one Python delivers SIGINT to, waits and every 50 ms takes the GIL back
// to run the signal handlers (PyErr_CheckSignals). Once a handler raised
// (KeyboardInterrupt), the core's thread pools - all of which poll one flag,
// set up at import (ThreadPool::set_default_cancel_check) - stop at their next
// poll, about a millisecond later, the work ends with Cancelled, and the
// Python exception is raised.
//
// C++ exceptions come back as Python's: std::invalid_argument as ValueError
// (pybind11's own translation); FileError (a file the system refused) as the
// OSError its errno names (FileNotFoundError, IsADirectoryError,
// PermissionError, ...); UnreadableFile (a file read_file_contents() could not
// parse) as OSError; any other std::runtime_error as RuntimeError. Each keeps
// the command line's message.
#include <functional>
#include <stdexcept>

#include "core/util/file_error.hpp"

namespace amls::python {

// Installs the pools' cancellation check; call once, at import.
void install_cancel_check();

// Runs `work` as above; call with the GIL held.
void run_released(const std::function<void()>& work);

// A file opened but not understood: a bad number, a truncated header, no points.
struct UnreadableFile : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// `read()`, a reader of one file, with its std::runtime_errors (other than
// FileError, which says more) thrown as UnreadableFile.
template <typename Read>
auto read_file_contents(Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const FileError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw UnreadableFile(e.what());
  }
}

// Raises the OSError subclass Python has for errno value `error` (OSError itself for 0 or one it has none for).
[[noreturn]] void raise_file_error(int error, const char* message);

}  // namespace amls::python
