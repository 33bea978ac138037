// Fuzz target: the point-set and mesh readers on a file whose extension is
// AMLS_FUZZ_EXTENSION (".ply", ".xyz", ".obj", ...; one target per extension).
// Any input must be read or refused with a message naming the file; a crash, a
// sanitizer report, a hang or an unnamed refusal is a finding.
#include <exception>
#include <string>

#include "core/io/mesh_io.hpp"
#include "core/io/point_set_io.hpp"
#include "fuzz/fuzz_support.hpp"

#ifndef AMLS_FUZZ_EXTENSION
#error "define AMLS_FUZZ_EXTENSION, e.g. \".ply\""
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = amls::fuzz::input_file(data, size, AMLS_FUZZ_EXTENSION);
  // The file decides its dimension, or 2 is forced (which checks every z).
  for (const int dimension : {0, 2}) {
    try {
      amls::read_point_set(path, dimension);
    } catch (const std::exception& e) {
      amls::fuzz::require_names_file(e.what(), path);
    }
  }
  try {
    if (amls::is_mesh_file(path)) amls::read_mesh(path);
  } catch (const std::exception& e) {
    amls::fuzz::require_names_file(e.what(), path);
  }
  return 0;
}
