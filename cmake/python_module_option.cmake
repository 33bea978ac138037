# AMLS_PYTHON: build the Python module `amls` (python/). Defaults to ON when Python 3's headers
# and pybind11 are found. Debian's /usr/bin/python3 is preferred over another python3 on PATH
# (pyenv), whose site-packages would lack python3-numpy and python3-open3d.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3)
endif()
set(amls_python_default OFF)
if(NOT AMLS_FUZZ AND NOT AMLS_SANITIZE_ADDRESS AND NOT AMLS_SANITIZE_THREAD)
  find_package(Python3 3.8 COMPONENTS Interpreter Development.Module QUIET)
  if(Python3_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
    if(pybind11_FOUND)
      set(amls_python_default ON)
    endif()
  endif()
endif()
option(AMLS_PYTHON "Build the Python module amls (needs python3-dev and pybind11-dev)" ${amls_python_default})
if(AMLS_PYTHON)
  find_package(Python3 3.8 REQUIRED COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.6 REQUIRED CONFIG)
  # The module is a shared object that links the static core libraries into itself.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()
message(STATUS "Python module: ${AMLS_PYTHON}")
