#include <doctest/doctest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "core/thread_pool.hpp"

using namespace amls;

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
  CHECK_THROWS_AS(pool.parallel_for(100, [](std::size_t b, std::size_t, int) {
    if (b > 0) throw std::runtime_error("boom");
  }), std::runtime_error);
  std::atomic<int> sum{0};
  pool.parallel_for(10, [&](std::size_t b, std::size_t e, int) { sum += static_cast<int>(e - b); });
  CHECK(sum == 10);
}
