#include <doctest/doctest.h>

#include <vector>

#include "core/util/process_memory.hpp"

using namespace amls;

namespace {

// Past glibc's largest mmap threshold (32 MiB): the block is mapped on its own
// and goes back to the system when freed.
constexpr std::size_t kBlockMiB = 96;

// Keeps the compiler from dropping an allocation nothing else reads.
void escape(const void* p) { asm volatile("" : : "r"(p) : "memory"); }

}  // namespace

TEST_CASE("process memory: the peak rises with an allocation, and a reset brings it back down") {
  REQUIRE(reset_peak_memory());
  const double start = peak_memory_mib();
  REQUIRE(start > 0.0);
  double high = 0.0;
  {
    std::vector<unsigned char> block(kBlockMiB << 20, 1);  // filled: every page resident
    escape(block.data());
    high = peak_memory_mib();
  }
  CHECK(high >= start + 0.9 * kBlockMiB);
  REQUIRE(reset_peak_memory());
  const double after = peak_memory_mib();
  CHECK(after <= high - 0.9 * kBlockMiB);
  CHECK(after > 0.0);
}
