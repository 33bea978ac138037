#include <doctest/doctest.h>

#include <sys/mman.h>

#include <cstring>

#include "core/util/process_memory.hpp"

using namespace amls;

namespace {

constexpr std::size_t kBlockMiB = 96;

// A block mapped and unmapped directly, not through malloc: whether a freed
// heap block goes back to the system depends on the allocator (glibc's mmap
// threshold; AddressSanitizer keeps freed memory in quarantine), and this test
// is about the measurement, not the allocator.
class ResidentBlock {
 public:
  explicit ResidentBlock(std::size_t bytes)
      : bytes_(bytes), data_(mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)) {
    REQUIRE(data_ != MAP_FAILED);
    std::memset(data_, 1, bytes_);  // every page resident
  }
  ~ResidentBlock() { munmap(data_, bytes_); }
  ResidentBlock(const ResidentBlock&) = delete;
  ResidentBlock& operator=(const ResidentBlock&) = delete;

 private:
  std::size_t bytes_;
  void* data_;
};

}  // namespace

TEST_CASE("process memory: the peak rises with an allocation, and a reset brings it back down") {
  REQUIRE(reset_peak_memory());
  const double start = peak_memory_mib();
  REQUIRE(start > 0.0);
  double high = 0.0;
  {
    const ResidentBlock block(kBlockMiB << 20);
    high = peak_memory_mib();
  }
  CHECK(high >= start + 0.9 * kBlockMiB);
  REQUIRE(reset_peak_memory());
  const double after = peak_memory_mib();
  CHECK(after <= high - 0.9 * kBlockMiB);
  CHECK(after > 0.0);
}
