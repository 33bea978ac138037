#pragma once
// The parts of the module, each bound by its own file.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace amls::python {

namespace py = pybind11;

void bind_files(py::module_& m);     // read, write, read_mesh (bind_files.cpp)
void bind_resample(py::module_& m);  // resample, mesh (bind_resample.cpp)
void bind_surface(py::module_& m);   // Surface, MlsDeformation (bind_surface.cpp)
void bind_scene(py::module_& m);     // run_scene (bind_scene.cpp)

// A JSON value (a report) as Python objects: dicts, lists, numbers, strings.
py::object to_python(const std::string& json_text);

// Issues a Python UserWarning for each of the core's warnings.
void warn_all(const std::vector<std::string>& warnings);

}  // namespace amls::python
