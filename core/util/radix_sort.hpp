#pragma once
// A stable least-significant-digit radix sort of (key, value) pairs by key.
// The point index sorts a few thousand Morton codes every step: one counting
// pass per byte in which the keys differ (usually 2 or 3) beats std::sort's
// n log n comparisons several times over. A million codes (a large surface's
// hash) are sorted on a pool: each block counts its own digits, and a
// digit's items go out block by block, so the order is the serial sort's.
#include <array>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/util/thread_pool.hpp"

namespace amls {

namespace radix_sort_detail {

using Counts = std::array<std::size_t, 256>;

inline std::size_t digit(std::uint64_t key, int shift) { return static_cast<std::size_t>((key >> shift) & 0xff); }

// The bits in which some key differs from the first.
template <typename Value>
std::uint64_t differing_bits(const std::vector<std::pair<std::uint64_t, Value>>& items, ThreadPool& pool) {
  std::vector<OwnCacheLine<std::uint64_t>> differing(static_cast<std::size_t>(pool.threads()), {0});
  const std::uint64_t first = items.front().first;
  pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int block) {
    std::uint64_t bits = 0;
    for (std::size_t i = begin; i < end; ++i) bits |= items[i].first ^ first;
    differing[static_cast<std::size_t>(block)].value |= bits;
  });
  std::uint64_t bits = 0;
  for (const auto& d : differing) bits |= d.value;
  return bits;
}

}  // namespace radix_sort_detail

// Sorts `items` by key, keeping equal keys in their order; `scratch` is
// working space (kept by the caller so that repeated sorts do not allocate).
template <typename Value>
void radix_sort_by_key(std::vector<std::pair<std::uint64_t, Value>>& items,
                       std::vector<std::pair<std::uint64_t, Value>>& scratch) {
  using radix_sort_detail::digit;
  if (items.size() < 2) return;
  std::uint64_t differing = 0;  // the bits in which some key differs from the first
  for (const auto& item : items) differing |= item.first ^ items.front().first;
  scratch.resize(items.size());
  for (int shift = 0; shift < 64 && (differing >> shift) != 0; shift += 8) {
    if (digit(differing, shift) == 0) continue;  // all keys share this byte
    radix_sort_detail::Counts start{};
    for (const auto& item : items) ++start[digit(item.first, shift)];
    std::size_t sum = 0;
    for (std::size_t& s : start) sum += std::exchange(s, sum);
    for (const auto& item : items) scratch[start[digit(item.first, shift)]++] = item;
    items.swap(scratch);
  }
}

// The same on `pool`: the same order for any thread count. Below a few
// thousand items it sorts serially, where the loops' hand-offs would cost
// more than they share. A one-thread pool takes the parallel path too (its
// loops run inline at the serial sort's cost), so that its serial share
// measures what more threads would leave serial.
template <typename Value>
void radix_sort_by_key(std::vector<std::pair<std::uint64_t, Value>>& items,
                       std::vector<std::pair<std::uint64_t, Value>>& scratch, ThreadPool& pool) {
  using radix_sort_detail::digit;
  constexpr std::size_t kSerialBelow = 16384;
  if (items.size() < kSerialBelow) {
    radix_sort_by_key(items, scratch);
    return;
  }
  const std::uint64_t differing = radix_sort_detail::differing_bits(items, pool);
  // Each block's next slot per digit. Both loops of a pass give block k the
  // same items (ThreadPool::parallel_for), so its counts are its cursors.
  std::vector<OwnCacheLine<radix_sort_detail::Counts>> cursors(static_cast<std::size_t>(pool.threads()));
  scratch.resize(items.size());
  for (int shift = 0; shift < 64 && (differing >> shift) != 0; shift += 8) {
    if (digit(differing, shift) == 0) continue;  // all keys share this byte
    pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int block) {
      radix_sort_detail::Counts& count = cursors[static_cast<std::size_t>(block)].value;
      for (std::size_t i = begin; i < end; ++i) ++count[digit(items[i].first, shift)];
    });
    // Digit by digit, block by block: the stable order.
    std::size_t sum = 0;
    for (std::size_t d = 0; d < 256; ++d)
      for (auto& cursor : cursors) sum += std::exchange(cursor.value[d], sum);
    pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int block) {
      radix_sort_detail::Counts& cursor = cursors[static_cast<std::size_t>(block)].value;
      for (std::size_t i = begin; i < end; ++i) scratch[cursor[digit(items[i].first, shift)]++] = items[i];
    });
    items.swap(scratch);
    for (auto& cursor : cursors) cursor.value.fill(0);
  }
}

}  // namespace amls
