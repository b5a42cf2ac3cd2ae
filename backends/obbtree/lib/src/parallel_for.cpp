#include "parallel_for.h"

#include <map>
#include <memory>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace collido::obbtree::detail {
namespace {

// One arena per thread count, made on first use and kept: making one per query would cost more
// than a small query.
tbb::task_arena& arenaFor(int threads) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
  if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
  return *arena;
}

}  // namespace

void parallelFor(int threads, std::size_t count, const std::function<void(std::size_t)>& body) {
  arenaFor(threads).execute([&] {
    // Grain 1: the items are subtrees of very uneven size.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t k = range.begin(); k != range.end(); ++k)
                          body(k);
                      });
  });
}

}  // namespace collido::obbtree::detail
