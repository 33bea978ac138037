#include "fuzz/fuzz_support.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace amls::fuzz {

std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const char* tmp = std::getenv("TMPDIR");
  const std::string path =
      std::string(tmp && *tmp ? tmp : "/tmp") + "/amls-fuzz-" + std::to_string(getpid()) + extension;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out.flush()) throw std::runtime_error("cannot write the fuzz input to " + path);
  return path;
}

void require_names_file(const std::string& message, const std::string& path) {
  if (message.find(path) != std::string::npos) return;
  std::fprintf(stderr, "a refusal that does not name the file %s: %s\n", path.c_str(), message.c_str());
  std::abort();
}

std::size_t Bytes::count(std::size_t lo, std::size_t hi) {
  const std::size_t value = static_cast<std::size_t>(byte()) | static_cast<std::size_t>(byte()) << 8;
  return lo + value % (hi - lo + 1);
}

double Bytes::number(double lo, double hi) {
  const double unit = static_cast<double>(count(0, 65535)) / 65535.0;
  return lo + unit * (hi - lo);
}

}  // namespace amls::fuzz
