// Tests of gecko/core/parallel.hpp: every item is visited exactly once for any thread count, blocks
// are contiguous and ordered, and the error rethrown is that of the lowest thread (for blocks: the
// smallest failing block), so what a batch call reports does not depend on the thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "gecko/core/parallel.hpp"

TEST_CASE("strided and block loops visit every item once", "[core][parallel]") {
  for (std::size_t count : {0u, 1u, 2u, 7u, 64u, 1001u}) {
    for (unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
      std::vector<std::atomic<int>> strided(count), blocks(count);
      gecko::detail::parallel_for_strided(count, threads, [&](std::size_t i) { ++strided[i]; });
      gecko::detail::parallel_for_blocks(count, threads, [&](std::size_t b, std::size_t e) {
        REQUIRE(b < e);
        for (std::size_t i = b; i < e; ++i) ++blocks[i];
      });
      for (std::size_t i = 0; i < count; ++i) {
        CHECK(strided[i] == 1);
        CHECK(blocks[i] == 1);
      }
    }
  }
}

TEST_CASE("blocks split the range into near-equal contiguous parts", "[core][parallel]") {
  std::vector<std::pair<std::size_t, std::size_t>> seen;
  std::mutex m;
  gecko::detail::parallel_for_blocks(10, 3, [&](std::size_t b, std::size_t e) {
    std::lock_guard<std::mutex> lock(m);
    seen.emplace_back(b, e);
  });
  std::sort(seen.begin(), seen.end());
  REQUIRE(seen.size() == 3);
  CHECK(seen[0] == std::make_pair(std::size_t(0), std::size_t(3)));
  CHECK(seen[1] == std::make_pair(std::size_t(3), std::size_t(6)));
  CHECK(seen[2] == std::make_pair(std::size_t(6), std::size_t(10)));
}

TEST_CASE("the lowest thread's error is rethrown after all joined", "[core][parallel]") {
  for (unsigned threads : {1u, 2u, 4u}) {
    std::atomic<int> done{0};
    try {
      gecko::detail::parallel_for_blocks(100, threads, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) {
          if (i == 30 || i == 90) throw std::domain_error("bad " + std::to_string(i));
          ++done;
        }
      });
      FAIL("no exception");
    } catch (const std::domain_error& err) {
      CHECK(std::string(err.what()) == "bad 30");
    }
    CHECK(done >= 30);  // the items before the failure in its block were computed
  }
}
