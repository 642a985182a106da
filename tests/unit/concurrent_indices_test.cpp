// forEachIndexConcurrently: every index runs once whatever the threads, and an
// exception from any thread reaches the caller instead of ending the process.
#include "driver/concurrent_indices.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <string>
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

// Two indices throw; the later one throws first in time. The caller sees the earlier
// index's exception, as one thread running the indices in order would.
TEST(ConcurrentIndices, TheLowestFailingIndexIsRethrownWhateverThreadThrewFirst) {
  std::mutex lock;
  std::condition_variable changed;
  bool laterThrew = false;
  auto fn = [&](std::size_t i) {
    if (i == 7) {
      std::lock_guard guard(lock);
      laterThrew = true;
      changed.notify_all();
      throw std::runtime_error("index 7");
    }
    if (i == 3) {
      std::unique_lock guard(lock);
      changed.wait(guard, [&] { return laterThrew; });
      throw std::runtime_error("index 3");
    }
  };
  try {
    wg::forEachIndexConcurrently(10, 4, fn);
    ADD_FAILURE() << "nothing thrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "index 3");
  }
}

// A process out of address space (or of threads) cannot start helpers: the calling
// thread does every index itself instead of the process ending in std::terminate.
TEST(ConcurrentIndices, ThreadsThatCannotStartLeaveTheWorkToTheCaller) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Room for small allocations, none for a thread's stack (8 MiB by default).
    std::ifstream status("/proc/self/status");
    long kib = 0;
    for (std::string key; status >> key;)
      if (key == "VmSize:") status >> kib;
    const rlimit limit{static_cast<rlim_t>(kib + 1024) * 1024, static_cast<rlim_t>(kib + 1024) * 1024};
    if (kib == 0 || ::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(3);
    std::vector<int> runs(8, 0);
    try {
      wg::forEachIndexConcurrently(runs.size(), 8, [&](std::size_t i) { ++runs[i]; });
    } catch (...) {
      ::_exit(2);
    }
    for (int r : runs)
      if (r != 1) ::_exit(1);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child ended on signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
