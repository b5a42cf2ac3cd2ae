#include <collido/runner/heap_probe.h>

#include <dlfcn.h>
#include <malloc.h>

#include <collido/runner/heap_hooks_api.h>

namespace collido {
namespace {

struct HookEntryPoints {
  CollidoHeapHooksRead read = nullptr;
  CollidoHeapHooksResetPeak reset_peak = nullptr;
};

// Looked up once: the hooks are either preloaded from the start or absent for good.
const HookEntryPoints& hooks() {
  static const HookEntryPoints entry_points = [] {
    HookEntryPoints found;
    // dlsym returns void*; converting it to a function pointer is what POSIX requires.
    found.read = reinterpret_cast<CollidoHeapHooksRead>(  // NOLINT
        dlsym(RTLD_DEFAULT, "collido_heap_hooks_read"));
    found.reset_peak = reinterpret_cast<CollidoHeapHooksResetPeak>(  // NOLINT
        dlsym(RTLD_DEFAULT, "collido_heap_hooks_reset_peak"));
    if (found.read == nullptr || found.reset_peak == nullptr) return HookEntryPoints{};
    return found;
  }();
  return entry_points;
}

std::optional<std::size_t> mallinfoBytes() {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const struct mallinfo2 info = mallinfo2();
  const std::size_t bytes = info.uordblks + info.hblkhd;
  // A process that has allocated (this one has) never reports zero through glibc; zero means
  // another allocator (a sanitizer's) answers malloc and the probe sees nothing.
  if (bytes == 0) return std::nullopt;
  return bytes;
#else
  return std::nullopt;
#endif
}

std::size_t nonNegative(std::int64_t value) {
  return value > 0 ? static_cast<std::size_t>(value) : 0;
}

}  // namespace

std::optional<HeapHookSample> heapHookSample() {
  if (hooks().read == nullptr) return std::nullopt;
  const CollidoHeapHookCounters counters = hooks().read();
  HeapHookSample sample;
  sample.live_bytes = nonNegative(counters.live_bytes);
  sample.peak_bytes = nonNegative(counters.peak_bytes);
  sample.allocations = counters.allocations;
  return sample;
}

void resetHeapPeak() {
  if (hooks().reset_peak != nullptr) hooks().reset_peak();
}

std::optional<std::size_t> heapBytesInUse() {
  if (const std::optional<HeapHookSample> sample = heapHookSample()) return sample->live_bytes;
  return mallinfoBytes();
}

std::string heapProbeName() {
  if (hooks().read != nullptr) return "hooks";
  return mallinfoBytes() ? "mallinfo2" : "none";
}

}  // namespace collido
