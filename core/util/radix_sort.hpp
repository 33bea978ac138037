#pragma once
// A stable least-significant-digit radix sort of (key, value) pairs by key.
// The point index sorts a few thousand Morton codes every step: one counting
// pass per byte in which the keys differ (usually 2 or 3) beats std::sort's
// n log n comparisons several times over.
#include <array>
#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace amls {

// Sorts `items` by key, keeping equal keys in their order; `scratch` is
// working space (kept by the caller so that repeated sorts do not allocate).
template <typename Value>
void radix_sort_by_key(std::vector<std::pair<std::uint64_t, Value>>& items,
                       std::vector<std::pair<std::uint64_t, Value>>& scratch) {
  if (items.size() < 2) return;
  std::uint64_t differing = 0;  // the bits in which some key differs from the first
  for (const auto& item : items) differing |= item.first ^ items.front().first;
  scratch.resize(items.size());
  for (int shift = 0; shift < 64 && (differing >> shift) != 0; shift += 8) {
    if (((differing >> shift) & 0xff) == 0) continue;  // all keys share this byte
    std::array<std::size_t, 256> start{};
    for (const auto& item : items) ++start[(item.first >> shift) & 0xff];
    std::size_t sum = 0;
    for (std::size_t& s : start) sum += std::exchange(s, sum);
    for (const auto& item : items) scratch[start[(item.first >> shift) & 0xff]++] = item;
    items.swap(scratch);
  }
}

}  // namespace amls
