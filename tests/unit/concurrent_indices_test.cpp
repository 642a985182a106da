// forEachIndexConcurrently: every index runs once whatever the threads, and an
// exception from any thread reaches the caller instead of ending the process.
#include "driver/concurrent_indices.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace {

TEST(ConcurrentIndices, EveryIndexRunsExactlyOnce) {
  for (int threads : {-1, 0, 1, 2, 4, 9})
    for (std::size_t count : {0u, 1u, 3u, 4u, 17u}) {
      std::vector<std::atomic<int>> runs(count);
      wg::forEachIndexConcurrently(count, threads, [&](std::size_t i) { ++runs[i]; });
      for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i], 1) << "index " << i << " of " << count << ", " << threads << " threads";
    }
}

TEST(ConcurrentIndices, AnExceptionOnAnyThreadReachesTheCaller) {
  for (int threads : {1, 4}) {
    std::atomic<int> started{0};
    EXPECT_THROW(wg::forEachIndexConcurrently(16, threads,
                                              [&](std::size_t i) {
                                                ++started;
                                                if (i == 2) throw std::runtime_error("stage 2");
                                              }),
                 std::runtime_error)
        << threads << " threads";
    EXPECT_GE(started, 3);
  }
}

}  // namespace
