// Allocation hooks preloaded (LD_PRELOAD) into study workers, so the bytes a backend's build
// allocates are counted by us, whatever the engine says about itself. Interposing malloc and
// friends catches C, C++ (operator new calls malloc) and every dlopen'ed plugin alike; the real
// work is forwarded to glibc's __libc_* entry points, which never call back into these hooks.
//
// Counters are relaxed atomics: a build is measured on one thread, and a slightly stale peak
// from another thread would only ever overstate, never hide, what was allocated.
#include <malloc.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdint>

#include <collido/runner/heap_hooks_api.h>

// glibc's own entry points: reserved names by design, the only way to reach the real allocator
// without calling back into these hooks.
// NOLINTBEGIN(bugprone-reserved-identifier)
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* pointer);
}
// NOLINTEND(bugprone-reserved-identifier)

namespace {

std::atomic<std::int64_t> live_bytes{0};
std::atomic<std::int64_t> peak_bytes{0};
std::atomic<std::uint64_t> allocation_count{0};

void notePeak(std::int64_t live) {
  std::int64_t peak = peak_bytes.load(std::memory_order_relaxed);
  while (live > peak && !peak_bytes.compare_exchange_weak(peak, live, std::memory_order_relaxed)) {
  }
}

void* counted(void* pointer) {
  if (pointer != nullptr) {
    const auto size = static_cast<std::int64_t>(malloc_usable_size(pointer));
    notePeak(live_bytes.fetch_add(size, std::memory_order_relaxed) + size);
    allocation_count.fetch_add(1, std::memory_order_relaxed);
  }
  return pointer;
}

void uncount(void* pointer) {
  if (pointer != nullptr) {
    live_bytes.fetch_sub(static_cast<std::int64_t>(malloc_usable_size(pointer)),
                         std::memory_order_relaxed);
  }
}

bool isPowerOfTwo(std::size_t value) {
  return value != 0 && (value & (value - 1)) == 0;
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) void* malloc(std::size_t size) {
  return counted(__libc_malloc(size));
}

__attribute__((visibility("default"))) void* calloc(std::size_t count, std::size_t size) {
  return counted(__libc_calloc(count, size));
}

__attribute__((visibility("default"))) void* realloc(void* pointer, std::size_t size) {
  // Uncount first: after a successful realloc the old block may be gone. If realloc fails the
  // old block survives, so it is counted again.
  uncount(pointer);
  void* moved = __libc_realloc(pointer, size);
  if (moved == nullptr && size != 0) return counted(pointer);
  return counted(moved);
}

__attribute__((visibility("default"))) void free(void* pointer) {
  uncount(pointer);
  __libc_free(pointer);
}

__attribute__((visibility("default"))) void* memalign(std::size_t alignment, std::size_t size) {
  return counted(__libc_memalign(alignment, size));
}

__attribute__((visibility("default"))) void* aligned_alloc(std::size_t alignment,
                                                           std::size_t size) {
  return counted(__libc_memalign(alignment, size));
}

__attribute__((visibility("default"))) int posix_memalign(void** out, std::size_t alignment,
                                                          std::size_t size) {
  if (!isPowerOfTwo(alignment) || alignment % sizeof(void*) != 0) return EINVAL;
  void* pointer = counted(__libc_memalign(alignment, size));
  if (pointer == nullptr && size != 0) return ENOMEM;
  *out = pointer;
  return 0;
}

__attribute__((visibility("default"))) CollidoHeapHookCounters collido_heap_hooks_read(void) {
  CollidoHeapHookCounters counters;
  counters.live_bytes = live_bytes.load(std::memory_order_relaxed);
  counters.peak_bytes = peak_bytes.load(std::memory_order_relaxed);
  counters.allocations = allocation_count.load(std::memory_order_relaxed);
  return counters;
}

__attribute__((visibility("default"))) void collido_heap_hooks_reset_peak(void) {
  peak_bytes.store(live_bytes.load(std::memory_order_relaxed), std::memory_order_relaxed);
}

}  // extern "C"
