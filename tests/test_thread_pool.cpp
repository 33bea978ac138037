#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/util/block_join.hpp"
#include "core/util/parallel_stopwatch.hpp"
#include "core/util/thread_pool.hpp"

using namespace amls;

namespace {

// The sub-ranges [begin, end) each block was called with, in call order.
using Calls = std::vector<std::vector<std::pair<std::size_t, std::size_t>>>;

// Runs parallel_for over [0, n), recording every call; the body keeps no state between calls.
Calls record_calls(ThreadPool& pool, std::size_t n) {
  Calls calls(static_cast<std::size_t>(pool.threads()));
  pool.parallel_for(
      n, [&](std::size_t b, std::size_t e, int block) { calls[static_cast<std::size_t>(block)].emplace_back(b, e); });
  return calls;
}

// Per-block output appended item by item and joined in block order, as the resampler does.
std::vector<std::size_t> joined_squares(ThreadPool& pool, std::size_t n) {
  std::vector<std::vector<std::size_t>> parts(static_cast<std::size_t>(pool.threads()));
  pool.parallel_for(n, [&](std::size_t b, std::size_t e, int block) {
    for (std::size_t i = b; i < e; ++i) parts[static_cast<std::size_t>(block)].push_back(i * i);
  });
  std::vector<std::size_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

}  // namespace

TEST_CASE("parallel_for covers every index exactly once, for any thread count") {
  for (int threads : {1, 2, 3, 8}) {
    ThreadPool pool(threads);
    for (std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<int> hits(n, 0);
      pool.parallel_for(n, [&](std::size_t b, std::size_t e, int) {
        for (std::size_t i = b; i < e; ++i) ++hits[i];
      });
      for (int h : hits) CHECK(h == 1);
    }
  }
}

TEST_CASE("parallel_for rethrows a block's exception and the pool stays usable") {
  ThreadPool pool(3);
  CHECK_THROWS_AS(pool.parallel_for(100,
                                    [](std::size_t b, std::size_t, int) {
                                      if (b > 0) throw std::runtime_error("boom");
                                    }),
                  std::runtime_error);
  std::atomic<int> sum{0};
  pool.parallel_for(10, [&](std::size_t b, std::size_t e, int) { sum += static_cast<int>(e - b); });
  CHECK(sum == 10);
}

TEST_CASE("under a cancellation check each block runs as consecutive sub-ranges covering it once, in order") {
  const std::size_t n = 100000;
  for (int threads : {1, 3}) {
    ThreadPool pool(threads);
    pool.set_cancel_check([] { return false; });
    const Calls calls = record_calls(pool, n);
    const auto blocks = static_cast<std::size_t>(threads);
    for (std::size_t block = 0; block < blocks; ++block) {
      const auto& ranges = calls[block];
      REQUIRE(ranges.size() > 1);  // split: the first sub-range is a single item
      CHECK(ranges.front().first == n * block / blocks);
      CHECK(ranges.back().second == n * (block + 1) / blocks);
      for (std::size_t k = 0; k < ranges.size(); ++k) {
        CHECK(ranges[k].first < ranges[k].second);
        if (k > 0) CHECK(ranges[k].first == ranges[k - 1].second);
      }
    }
  }
}

TEST_CASE("sub-ranges change no result: per-block output joined in block order is the same for 1 and 3 threads") {
  const std::size_t n = 50000;
  ThreadPool one(1);
  const std::vector<std::size_t> expected = joined_squares(one, n);  // one call, no check
  REQUIRE(expected.size() == n);
  for (int threads : {1, 3}) {
    ThreadPool pool(threads);
    CHECK(joined_squares(pool, n) == expected);
    pool.set_cancel_check([] { return false; });
    CHECK(joined_squares(pool, n) == expected);
  }
}

TEST_CASE("a cancellation stops every block at its next sub-range and parallel_for throws Cancelled") {
  const std::size_t n = 3000000;
  const std::size_t trigger = 100;  // in block 0
  for (int threads : {1, 3}) {
    CAPTURE(threads);
    ThreadPool pool(threads);
    std::atomic<bool> stop{false};
    pool.set_cancel_check([&] { return stop.load(); });
    const auto blocks = static_cast<std::size_t>(threads);
    // Each block is touched by one thread only.
    std::vector<std::size_t> processed(blocks, 0), late_calls(blocks, 0);
    // The other blocks start, then wait in their first item for the cancel, so
    // that every block is under way when it comes and none can finish before
    // it, whatever the scheduling.
    std::atomic<std::size_t> started{0};
    auto body = [&](std::size_t b, std::size_t e, int block) {
      const auto k = static_cast<std::size_t>(block);
      if (stop.load()) ++late_calls[k];
      if (block > 0 && processed[k] == 0) {
        ++started;
        started.notify_all();
        stop.wait(false);
      }
      for (std::size_t i = b; i < e; ++i) {
        if (i == trigger) {
          for (std::size_t s = started.load(); s < blocks - 1; s = started.load()) started.wait(s);
          stop = true;
          stop.notify_all();
        }
        ++processed[k];
      }
    };
    CHECK_THROWS_AS(pool.parallel_for(n, body), Cancelled);
    CHECK(processed[0] > trigger);
    CHECK(processed[0] < n / blocks);
    for (std::size_t k = 1; k < blocks; ++k) CHECK(processed[k] == 1);
    for (std::size_t k = 0; k < blocks; ++k) CHECK(late_calls[k] == 0);

    // The pool stays usable: the same check, no longer true, lets everything run.
    stop = false;
    std::atomic<std::size_t> total{0};
    pool.parallel_for(n, [&](std::size_t b, std::size_t e, int) { total += e - b; });
    CHECK(total == n);
  }
}

TEST_CASE("a check already true stops before any work, even with one item or one thread") {
  for (int threads : {1, 3}) {
    ThreadPool pool(threads);
    pool.set_cancel_check([] { return true; });
    for (std::size_t n : {1u, 1000u}) {
      std::atomic<int> calls{0};
      CHECK_THROWS_AS(pool.parallel_for(n, [&](std::size_t, std::size_t, int) { ++calls; }), Cancelled);
      CHECK(calls == 0);
    }
    pool.parallel_for(0, [](std::size_t, std::size_t, int) {});  // nothing to stop: no throw
  }
}

TEST_CASE("a block's own exception wins over the cancel it caused") {
  ThreadPool pool(3);
  std::atomic<bool> stop{false};
  pool.set_cancel_check([&] { return stop.load(); });
  CHECK_THROWS_AS(pool.parallel_for(3000,
                                    [&](std::size_t b, std::size_t, int block) {
                                      if (block == 1 && b == 1000) {
                                        stop = true;
                                        throw std::runtime_error("boom");
                                      }
                                    }),
                  std::runtime_error);
}

TEST_CASE("a CancelScope removes its check at the end: later loops run whole, one call per block") {
  ThreadPool pool(3);
  {
    CancelScope scope(pool, [] { return true; });
    CHECK_THROWS_AS(record_calls(pool, 300), Cancelled);
  }
  const Calls calls = record_calls(pool, 300);
  for (std::size_t block = 0; block < 3; ++block) {
    REQUIRE(calls[block].size() == 1);
    CHECK(calls[block][0] == std::pair<std::size_t, std::size_t>(100 * block, 100 * (block + 1)));
  }
}

TEST_CASE("poll_cancel throws Cancelled only while a check says stop") {
  ThreadPool pool(1);
  CHECK_NOTHROW(pool.poll_cancel());
  bool stop = false;
  pool.set_cancel_check([&] { return stop; });
  CHECK_NOTHROW(pool.poll_cancel());
  stop = true;
  CHECK_THROWS_AS(pool.poll_cancel(), Cancelled);
  pool.set_cancel_check({});
  CHECK_NOTHROW(pool.poll_cancel());
}

TEST_CASE("pools start with the default cancellation check; a CancelScope puts the pool's own check back") {
  std::atomic<bool> stop = false;
  ThreadPool::set_default_cancel_check([&] { return stop.load(); });
  ThreadPool pool(2);
  ThreadPool::set_default_cancel_check({});
  ThreadPool unchecked(2);
  CHECK_NOTHROW(record_calls(pool, 100));
  stop = true;
  CHECK_THROWS_AS(record_calls(pool, 100), Cancelled);
  CHECK_THROWS_AS(pool.poll_cancel(), Cancelled);
  CHECK_NOTHROW(record_calls(unchecked, 100));  // made after the default was removed
  stop = false;
  {
    CancelScope scope(pool, [] { return true; });
    CHECK_THROWS_AS(record_calls(pool, 100), Cancelled);
  }
  stop = true;
  CHECK_THROWS_AS(record_calls(pool, 100), Cancelled);  // the default check again, not none
}

namespace {

// Deterministic busy work: a sum no compiler can fold away.
double busy_sum(std::size_t begin, std::size_t end) {
  double sum = 0.0;
  for (std::size_t i = begin; i < end; ++i) sum += std::sqrt(static_cast<double>(i) + 0.5);
  return sum;
}

}  // namespace

TEST_CASE("serial share: work outside parallel loops is all serial, and a loop of one item is serial") {
  ThreadPool pool(2);
  ParallelStopwatch clock;
  volatile double sink = busy_sum(0, 2000000);
  pool.parallel_for(1, [&](std::size_t b, std::size_t e, int) { sink = sink + busy_sum(b, e * 2000000); });
  const ParallelLap lap = clock.lap();
  CHECK(lap.parallel == 0.0);
  CHECK(lap.wall > 0.0);
  CHECK(lap.serial_share() == 1.0);
}

TEST_CASE("serial share: a run that is all one parallel loop has a share near 0, on one thread as on three") {
  for (const int threads : {1, 3}) {
    ThreadPool pool(threads);
    std::vector<double> sums(static_cast<std::size_t>(threads), 0.0);
    ParallelStopwatch clock;
    pool.parallel_for(30000000, [&](std::size_t b, std::size_t e, int block) {
      sums[static_cast<std::size_t>(block)] += busy_sum(b, e);
    });
    const ParallelLap lap = clock.lap();
    CHECK(sums[0] > 0.0);
    CHECK(lap.parallel > 0.0);
    CHECK(lap.parallel <= lap.wall);
    // Outside the loop are two clock reads: a share of 0.5 would take a pause
    // as long as the loop's work between them.
    CHECK(lap.serial_share() < 0.5);
  }
}

TEST_CASE("serial share: a loop run inside another loop's body counts once") {
  // The outer pool has one thread, so its body, and the inner loop, run on the counting thread.
  ThreadPool outer(1), inner(2);
  ParallelStopwatch clock;
  std::vector<double> sums(2, 0.0);
  // All the work is in the inner loop; counted twice it would exceed the wall time.
  outer.parallel_for(2, [&](std::size_t, std::size_t, int) {
    inner.parallel_for(20000000, [&](std::size_t ib, std::size_t ie, int block) {
      sums[static_cast<std::size_t>(block)] += busy_sum(ib, ie);
    });
  });
  const ParallelLap lap = clock.lap();
  CHECK(lap.parallel > 0.0);
  CHECK(lap.parallel <= lap.wall);
}

TEST_CASE("join_blocks joins the blocks' lists in block order and keeps none of the old contents") {
  for (const int threads : {1, 2, 5}) {
    ThreadPool pool(threads);
    std::vector<OwnCacheLine<std::vector<std::size_t>>> parts(static_cast<std::size_t>(threads));
    pool.parallel_for(1001, [&](std::size_t b, std::size_t e, int block) {
      for (std::size_t i = b; i < e; ++i) parts[static_cast<std::size_t>(block)].value.push_back(i * i);
    });
    std::vector<std::size_t> out(5000, 7);  // longer than the result: it must shrink
    join_blocks(parts, out, pool);
    REQUIRE(out.size() == 1001);
    for (std::size_t i = 0; i < out.size(); ++i) CHECK(out[i] == i * i);
  }
}
