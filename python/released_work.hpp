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
// (pybind11's own translation), and with `files` set, every other
// std::runtime_error as OSError (FileNotFoundError for a path that does not
// exist), since the core reports a file it cannot read or write so.
#include <functional>
#include <string>

namespace amls::python {

// Installs the pools' cancellation check; call once, at import.
void install_cancel_check();

struct WorkFiles {
  bool files = false;       // runtime errors are about files: OSError
  std::string missing_path;  // FileNotFoundError if this path does not exist ("" : none)
};

// Runs `work` as above; call with the GIL held.
void run_released(const std::function<void()>& work, const WorkFiles& files = {});

}  // namespace amls::python
