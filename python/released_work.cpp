#include "python/released_work.hpp"

#include <pybind11/pybind11.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <exception>
#include <future>
#include <stdexcept>

#include "core/util/thread_pool.hpp"

namespace amls::python {

namespace py = pybind11;

namespace {

// Set while a SIGINT handler has raised and the work it interrupted winds down.
std::atomic<bool> stop_requested{false};

// How often the waiting thread looks for signals: well within a second.
constexpr auto kSignalPoll = std::chrono::milliseconds(50);

[[noreturn]] void raise_python(PyObject* type, const char* message) {
  PyErr_SetString(type, message);
  throw py::error_already_set();
}

}  // namespace

void install_cancel_check() {
  ThreadPool::set_default_cancel_check([] { return stop_requested.load(std::memory_order_relaxed); });
}

void raise_file_error(int error, const char* message) {
  PyObject* type = PyExc_OSError;
  switch (error) {
    case ENOENT:
      type = PyExc_FileNotFoundError;
      break;
    case EISDIR:
      type = PyExc_IsADirectoryError;
      break;
    case ENOTDIR:
      type = PyExc_NotADirectoryError;
      break;
    case EEXIST:
      type = PyExc_FileExistsError;
      break;
    case EACCES:
    case EPERM:
      type = PyExc_PermissionError;
      break;
    default:
      break;
  }
  raise_python(type, message);
}

void run_released(const std::function<void()>& work) {
  std::future<void> done;
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    done = std::async(std::launch::async, work);
    while (done.wait_for(kSignalPoll) != std::future_status::ready) {
      if (interrupted) continue;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        // The handler's exception stays set until it is raised below.
        interrupted = true;
        stop_requested = true;
      }
    }
    done.wait();
  }
  if (interrupted) {
    stop_requested = false;
    throw py::error_already_set();
  }
  try {
    done.get();
  } catch (const Cancelled& e) {
    raise_python(PyExc_KeyboardInterrupt, e.what());
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const FileError& e) {
    raise_file_error(e.error(), e.what());
  } catch (const UnreadableFile& e) {
    raise_python(PyExc_OSError, e.what());
  }
}

}  // namespace amls::python
