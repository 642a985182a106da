#include "driver/concurrent_indices.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace wg {

void forEachIndexConcurrently(std::size_t count, int threads, const std::function<void(std::size_t)>& fn) {
  std::atomic<std::size_t> next{0};
  std::mutex failureLock;
  std::exception_ptr failure;
  std::size_t failedIndex = count;
  // An exception ends the loop and reaches the caller, as it would without threads.
  // Indices are taken in order, so every one below a failing index has run when the
  // threads stop: the lowest failing index's exception is the one a single thread
  // would have thrown, whichever thread threw first.
  auto worker = [&] {
    std::size_t i = 0;
    try {
      for (i = next++; i < count; i = next++) fn(i);
    } catch (...) {
      next = count;
      std::lock_guard lock(failureLock);
      if (i < failedIndex) {
        failedIndex = i;
        failure = std::current_exception();
      }
    }
  };
  const std::size_t helpers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count);
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  // A thread that cannot start (no memory for its stack, a process limit) leaves its
  // share to the others; the calling thread alone still does every index.
  try {
    for (std::size_t t = 1; t < helpers; ++t) pool.emplace_back(worker);
  } catch (const std::system_error&) {
  }
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace wg
