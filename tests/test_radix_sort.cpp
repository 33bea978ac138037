#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "core/util/radix_sort.hpp"

using namespace amls;

namespace {

using Items = std::vector<std::pair<std::uint64_t, std::uint32_t>>;

// Values are the items' original positions, so that a stable sort is the only right answer.
Items numbered(const std::vector<std::uint64_t>& keys) {
  Items items;
  for (std::uint32_t i = 0; i < keys.size(); ++i) items.emplace_back(keys[i], i);
  return items;
}

void check_sorts_like_stable_sort(const std::vector<std::uint64_t>& keys) {
  Items items = numbered(keys), scratch;
  Items expected = items;
  std::stable_sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  radix_sort_by_key(items, scratch);
  CHECK(items == expected);
}

}  // namespace

TEST_CASE("radix_sort_by_key: sorts as std::stable_sort does, equal keys in their order") {
  std::mt19937_64 random(11);
  SUBCASE("random 64-bit keys") {
    std::vector<std::uint64_t> keys(5000);
    for (auto& k : keys) k = random();
    check_sorts_like_stable_sort(keys);
  }
  SUBCASE("few distinct keys: long runs of equal keys") {
    std::vector<std::uint64_t> keys(5000);
    for (auto& k : keys) k = random() % 7;
    check_sorts_like_stable_sort(keys);
  }
  SUBCASE("keys differing only in their high bytes, and in bytes with equal bytes between them") {
    std::vector<std::uint64_t> keys(3000);
    for (auto& k : keys) k = ((random() % 256) << 56) | ((random() % 256) << 16) | 0x0000abcd0000ef01ULL;
    check_sorts_like_stable_sort(keys);
  }
  SUBCASE("already sorted, reversed, and all equal") {
    std::vector<std::uint64_t> keys(1000);
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = i * 977;
    check_sorts_like_stable_sort(keys);
    std::reverse(keys.begin(), keys.end());
    check_sorts_like_stable_sort(keys);
    std::fill(keys.begin(), keys.end(), ~std::uint64_t{0});
    check_sorts_like_stable_sort(keys);
  }
  SUBCASE("empty and single items") {
    check_sorts_like_stable_sort({});
    check_sorts_like_stable_sort({42});
  }
}

TEST_CASE("radix_sort_by_key: a scratch buffer left from a larger sort is reused") {
  Items scratch(10000, {1, 1});
  Items items = numbered({5, 3, 9, 3, 0});
  radix_sort_by_key(items, scratch);
  CHECK(items == Items{{0, 4}, {3, 1}, {3, 3}, {5, 0}, {9, 2}});
}

TEST_CASE("radix_sort_by_key on a pool: the serial sort's order for any thread count, whole blocks or in pieces") {
  std::mt19937_64 random(17);
  // Above the size the pooled sort sorts serially below; keys that differ
  // in a few bytes (as Morton codes of nearby cells) and in all of them.
  std::vector<std::uint64_t> few_bytes(70001), all_bytes(40000);
  for (auto& k : few_bytes) k = (random() % 5000) << 12 | 0x3;
  for (auto& k : all_bytes) k = random();
  for (const std::vector<std::uint64_t>* keys : {&few_bytes, &all_bytes}) {
    Items expected = numbered(*keys), scratch;
    std::stable_sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const int threads : {1, 2, 3, 8}) {
      ThreadPool pool(threads);
      Items items = numbered(*keys);
      radix_sort_by_key(items, scratch, pool);
      CHECK(items == expected);
      // Under a cancellation check each block runs as several sub-ranges.
      const CancelScope pieces(pool, [] { return false; });
      items = numbered(*keys);
      radix_sort_by_key(items, scratch, pool);
      CHECK(items == expected);
    }
  }
}
