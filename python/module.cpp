// The Python module `amls` (docs/python.md).
#include "python/bindings.hpp"
#include "python/released_work.hpp"

namespace amls::python {

py::object to_python(const std::string& json_text) { return py::module_::import("json").attr("loads")(json_text); }

void warn_all(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) < 0) throw py::error_already_set();  // warnings as errors
}

}  // namespace amls::python

PYBIND11_MODULE(amls, m) {
  m.doc() =
      "amls - deforming point-set (AMLS) surfaces with grid-based resampling, after 'Resampling Strategies for\n"
      "Deforming MLS Surfaces'. The command line's work on numpy arrays: read and write point sets (read, write,\n"
      "read_mesh), one resampling (resample) and its mesh (mesh), a surface to evaluate, resample and deform\n"
      "step by step (Surface, MlsDeformation) and scene files (run_scene). Points are float64 arrays of shape\n"
      "(n, 3), or (n, 2) for curves. Long calls release the GIL and stop on Ctrl+C (KeyboardInterrupt);\n"
      "results never depend on threads=. docs/python.md walks through it.";
  // Each docstring opens with its own signature, in Python's terms (as the stub has it).
  pybind11::options options;
  options.disable_function_signatures();
  m.attr("__version__") = "0.1.0";
  amls::python::install_cancel_check();
  amls::python::bind_files(m);
  amls::python::bind_resample(m);
  amls::python::bind_surface(m);
  amls::python::bind_scene(m);
}
