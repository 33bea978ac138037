#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <vector>

#include "core/util/default_init_allocator.hpp"
#include "core/util/parallel_compact.hpp"

using namespace amls;

namespace {

struct Item {  // plain data, as the resampler's crossings
  std::uint32_t key;
  double value;
  bool operator==(const Item& o) const { return key == o.key && value == o.value; }
};
using Items = std::vector<Item, DefaultInitAllocator<Item>>;

Items random_items(std::size_t n, std::uint32_t keys) {
  std::mt19937 random(7);
  std::uniform_int_distribution<std::uint32_t> key(0, keys - 1);
  Items items(n);
  for (std::size_t i = 0; i < n; ++i) items[i] = {key(random), static_cast<double>(i)};
  return items;
}

}  // namespace

TEST_CASE("keep_in_order keeps what a serial filter keeps, in its order, for any thread count") {
  const Items items = random_items(100'003, 10);
  auto keep = [](const Item& item, std::size_t index) { return item.key < 3 || index % 97 == 0; };
  Items expected;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (keep(items[i], i)) expected.push_back(items[i]);
  REQUIRE(expected.size() > 1000);
  REQUIRE(expected.size() < items.size());
  for (const int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    Items kept = items, scratch;
    keep_in_order(kept, scratch, keep, pool);
    CHECK(kept == expected);
    // The scratch can be reused: a second filter of the result by another rule.
    keep_in_order(kept, scratch, [](const Item& item, std::size_t) { return item.key == 0; }, pool);
    CHECK(std::all_of(kept.begin(), kept.end(), [](const Item& item) { return item.key == 0; }));
    CHECK(std::is_sorted(kept.begin(), kept.end(), [](const Item& a, const Item& b) { return a.value < b.value; }));
  }
}

TEST_CASE("keep_in_order also when the pool runs each block in pieces (a cancellation check installed)") {
  const Items items = random_items(300'000, 5);
  auto keep = [](const Item& item, std::size_t) { return item.key == 1; };
  Items expected;
  for (const Item& item : items)
    if (keep(item, 0)) expected.push_back(item);
  ThreadPool pool(3);
  CancelScope never(pool, [] { return false; });
  Items kept = items, scratch;
  keep_in_order(kept, scratch, keep, pool);
  CHECK(kept == expected);
}

TEST_CASE("keep_in_order of nothing, and of all") {
  ThreadPool pool(2);
  Items none, scratch;
  keep_in_order(none, scratch, [](const Item&, std::size_t) { return true; }, pool);
  CHECK(none.empty());
  Items all = random_items(1000, 4);
  const Items before = all;
  keep_in_order(all, scratch, [](const Item&, std::size_t) { return true; }, pool);
  CHECK(all == before);
  keep_in_order(all, scratch, [](const Item&, std::size_t) { return false; }, pool);
  CHECK(all.empty());
}

TEST_CASE("lower_to leaves each slot at the smallest value offered by any thread") {
  const Items items = random_items(200'000, 1000);
  std::vector<double> expected(1000, 1e300);
  for (const Item& item : items) expected[item.key] = std::min(expected[item.key], item.value);
  for (const int threads : {1, 4}) {
    ThreadPool pool(threads);
    std::vector<double> lowest(1000, 1e300);
    std::vector<std::uint32_t> count(1000, 0);
    pool.parallel_for(items.size(), [&](std::size_t begin, std::size_t end, int) {
      for (std::size_t i = begin; i < end; ++i) {
        lower_to(lowest[items[i].key], items[i].value);
        store_shared(count[items[i].key], std::uint32_t{1});
      }
    });
    CHECK(lowest == expected);
    CHECK(std::all_of(count.begin(), count.end(), [](std::uint32_t c) { return c == 1; }));
  }
}

TEST_CASE("DefaultInitAllocator: a vector that keeps its items through growth and copies") {
  Items items;
  for (std::uint32_t i = 0; i < 5000; ++i) items.push_back({i, 0.5 * i});
  items.resize(10);
  items.resize(20);  // the added items are unspecified; the kept ones are the same
  for (std::uint32_t i = 0; i < 10; ++i) CHECK(items[i] == Item{i, 0.5 * i});
  const Items copy(items.begin(), items.begin() + 10);
  CHECK(copy.size() == 10);
  CHECK(copy.back() == Item{9, 4.5});
  std::vector<double, DefaultInitAllocator<double>> filled(3, 2.0);  // constructions with a value keep it
  CHECK(filled == std::vector<double, DefaultInitAllocator<double>>{2.0, 2.0, 2.0});
}
