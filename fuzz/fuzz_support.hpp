#pragma once
// What the fuzz targets share: the libFuzzer entry point's signature, a file
// holding the input (the readers read files), a check that a refusal names its
// file, and a reader of typed values from the input's bytes.
#include <cstddef>
#include <cstdint>
#include <string>

// Defined by each target; libFuzzer calls it, and so does the replay program.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace amls::fuzz {

// Writes the bytes to a file of this process with the given extension
// (".ply", ...) in $TMPDIR (or /tmp) and returns its path; the same path for
// every call of the process, so nothing piles up.
std::string input_file(const std::uint8_t* data, std::size_t size, const std::string& extension);

// Aborts (a finding) unless `message` names `path`: every refusal of a file
// must say which file it is.
void require_names_file(const std::string& message, const std::string& path);

// Typed values taken from the front of the input; past its end, zeros.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return used_ < size_ ? data_[used_++] : 0; }
  // A whole number in [lo, hi].
  std::size_t count(std::size_t lo, std::size_t hi);
  // A number in [lo, hi], on a grid of 2^16 steps.
  double number(double lo, double hi);
  bool flag() { return (byte() & 1) != 0; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t used_ = 0;
};

}  // namespace amls::fuzz
