#pragma once
// Where the real-data tests find third-party files: CGAL's demo data
// (Debian's libcgal-demo), unpacked by the `cgal_data` test fixture into the
// folder named by AMLS_CGAL_DATA.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

namespace amls::test {

inline std::string data_file(const std::string& name) {
  const char* folder = std::getenv("AMLS_CGAL_DATA");
  REQUIRE_MESSAGE(folder != nullptr, "AMLS_CGAL_DATA names no folder: run this through ctest (label realdata)");
  return std::string(folder) + "/" + name;
}

}  // namespace amls::test
