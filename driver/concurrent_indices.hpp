// Runs fn(0..count-1) on up to `threads` threads, the calling one among them. Each
// thread takes the next index in turn, so indices given in order of cost (largest
// first) balance the threads. Once every thread has stopped, the exception of the
// lowest index that threw is rethrown to the caller: the one a single thread would
// throw, whatever the count. Threads that cannot be started leave their share to the
// others.
#pragma once
#include <cstddef>
#include <functional>

namespace wg {

void forEachIndexConcurrently(std::size_t count, int threads, const std::function<void(std::size_t)>& fn);

}  // namespace wg
