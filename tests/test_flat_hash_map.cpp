#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <unordered_map>

#include "core/util/flat_hash_map.hpp"

using namespace amls;

TEST_CASE("FlatHashMap: inserts, finds and counts like std::unordered_map through growth and clearing") {
  std::mt19937_64 random(7);
  FlatHashMap<int> map;  // 16 slots at first: grows many times
  std::unordered_map<std::uint64_t, int> expected;
  // Keys from a small range (many repeats) and from all of 64 bits, and
  // neighbouring grid-like keys that differ in a few low bits.
  auto key = [&](int i) -> std::uint64_t {
    switch (i % 3) {
      case 0:
        return random() % 5000;
      case 1:
        return random() >> 1;  // never kEmpty
      default:
        return (std::uint64_t{1} << 40) + static_cast<std::uint64_t>(i);
    }
  };
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t k = key(i);
    const auto [value, inserted] = map.try_emplace(k);
    const bool new_key = expected.find(k) == expected.end();
    REQUIRE(inserted == new_key);
    if (inserted) CHECK(*value == 0);  // default-constructed
    *value += i;
    expected[k] += i;
  }
  CHECK(map.size() == expected.size());
  for (const auto& [k, v] : expected) {
    const int* found = map.find(k);
    REQUIRE(found != nullptr);
    CHECK(*found == v);
  }
  for (int i = 0; i < 1000; ++i) {
    const std::uint64_t absent = (std::uint64_t{1} << 62) + static_cast<std::uint64_t>(i);
    CHECK(map.find(absent) == nullptr);
  }
  std::size_t visited = 0;
  map.for_each([&](std::uint64_t k, int v) {
    ++visited;
    CHECK(expected.at(k) == v);
  });
  CHECK(visited == expected.size());

  map.clear();
  CHECK(map.size() == 0);
  for (const auto& [k, v] : expected) CHECK(map.find(k) == nullptr);
  CHECK(map.try_emplace(42).second);
  CHECK(map.size() == 1);
}

TEST_CASE("FlatHashMap: reserve keeps what is stored, and a table at its load limit still finds every key") {
  FlatHashMap<std::uint64_t> map(4);
  for (std::uint64_t k = 0; k < 7; ++k) *map.try_emplace(k).first = k * k;  // 7 of 16 slots
  map.reserve(1000);
  CHECK(map.size() == 7);
  for (std::uint64_t k = 0; k < 7; ++k) {
    REQUIRE(map.find(k) != nullptr);
    CHECK(*map.find(k) == k * k);
  }
  // 8 keys in 16 slots, the most before it grows: probe runs are at their longest.
  FlatHashMap<std::uint64_t> full(8);
  for (std::uint64_t k = 0; k < 8; ++k) full.try_emplace(k * 0x9e3779b97f4a7c15ULL);
  CHECK(full.size() == 8);
  for (std::uint64_t k = 0; k < 8; ++k) CHECK(full.find(k * 0x9e3779b97f4a7c15ULL) != nullptr);
  CHECK(full.find(12345) == nullptr);
}
