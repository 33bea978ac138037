#pragma once
// Joins the lists that the blocks of a ThreadPool::parallel_for appended to,
// in block order, with the copying shared among the pool's threads: a million
// items copied by one thread is a serial stretch in the middle of a step.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/util/thread_pool.hpp"

namespace amls {

// Replaces `out` (a vector of T, with any allocator) by the parts one after
// the other. `out` is resized, not cleared first, so that a vector kept
// between calls constructs only the items it did not hold yet (and none with
// DefaultInitAllocator and plain items).
template <typename T, typename Out>
void join_blocks(const std::vector<OwnCacheLine<std::vector<T>>>& parts, Out& out, ThreadPool& pool) {
  std::vector<std::size_t> starts(parts.size() + 1, 0);
  for (std::size_t p = 0; p < parts.size(); ++p) starts[p + 1] = starts[p] + parts[p].value.size();
  out.resize(starts.back());
  // One part per block with as many parts as threads: parts of about equal
  // size (equal blocks of the same loop) keep every thread busy.
  pool.parallel_for(parts.size(), [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t p = begin; p < end; ++p)
      std::copy(parts[p].value.begin(), parts[p].value.end(), out.begin() + static_cast<std::ptrdiff_t>(starts[p]));
  });
}

}  // namespace amls
