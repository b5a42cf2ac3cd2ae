// Runs a loop body over [0, count) on a fixed number of threads (oneTBB), so the query code
// does not see the threading library.
#pragma once

#include <cstddef>
#include <functional>

namespace collido::obbtree::detail {

/// Calls body(k) for every k in [0, count), on up to `threads` threads of a pool kept for that
/// thread count (the calling thread takes part). Returns when every call has returned.
void parallelFor(int threads, std::size_t count, const std::function<void(std::size_t)>& body);

}  // namespace collido::obbtree::detail
