#pragma once
// Order-keeping filters and per-slot minima shared among a pool's threads.
// The resampler cuts lists of millions of crossings several times a step, and
// HAVECLOSEPOINT takes a minimum per grid vertex over them: done by one thread
// they were the largest serial stretch left in a step on many cores.
#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/util/thread_pool.hpp"

namespace amls {

// Keeps the items for which keep(item, index) holds, in their order. `keep`
// is called twice per item (once to count, once to copy) and must answer the
// same both times. The result is the serial filter's for any thread count.
// The kept items are copied to `scratch`, which is then swapped with `items`:
// a scratch kept by the caller (with DefaultInitAllocator for vectors of
// plain items) costs no allocation and no serial initialisation per call.
template <typename Items, typename Keep>
void keep_in_order(Items& items, Items& scratch, Keep&& keep, ThreadPool& pool) {
  // A block's kept count, then where its kept items start in the result.
  std::vector<OwnCacheLine<std::size_t>> cursor(static_cast<std::size_t>(pool.threads()), {0});
  pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::size_t kept = 0;
    for (std::size_t i = begin; i < end; ++i) kept += keep(items[i], i) ? 1 : 0;
    cursor[static_cast<std::size_t>(block)].value += kept;
  });
  std::size_t total = 0;
  for (auto& c : cursor) total += std::exchange(c.value, total);
  scratch.resize(total);
  // Block k covers the same items as in the counting loop (ThreadPool's
  // promise), and its pieces run in order, so each writes where it counted.
  pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::size_t& at = cursor[static_cast<std::size_t>(block)].value;
    for (std::size_t i = begin; i < end; ++i)
      if (keep(items[i], i)) scratch[at++] = items[i];
  });
  items.swap(scratch);
}

// Lowers `slot` to `value` if that is smaller; the slot ends at the minimum of
// all values offered, whichever thread offers which first.
template <typename T>
void lower_to(T& slot, T value) {
  std::atomic_ref<T> ref(slot);
  T current = ref.load(std::memory_order_relaxed);
  while (value < current && !ref.compare_exchange_weak(current, value, std::memory_order_relaxed)) {
  }
}

// Sets a slot that several threads may set to the same value at once.
template <typename T>
void store_shared(T& slot, T value) {
  std::atomic_ref<T>(slot).store(value, std::memory_order_relaxed);
}

}  // namespace amls
