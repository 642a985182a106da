// Runs fn(0..count-1) on up to `threads` threads, the calling one among them. Each
// thread takes the next index in turn, so indices given in order of cost (largest
// first) balance the threads. The first exception thrown is rethrown to the caller
// once every thread has stopped.
#pragma once
#include <cstddef>
#include <functional>

namespace wg {

void forEachIndexConcurrently(std::size_t count, int threads, const std::function<void(std::size_t)>& fn);

}  // namespace wg
