#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace collido {

/// Bytes the C heap currently has handed out. With the allocation hooks preloaded
/// (libcollido_heap_hooks.so, as study workers run) this is their exact live count; otherwise
/// glibc's mallinfo2 (arena plus mmapped chunks). Either counts every allocation of the process,
/// engines' included, so the difference around a build measures what the build kept,
/// independently of what the backend says. Empty when no probe works here (e.g. under
/// AddressSanitizer, whose allocator glibc does not see).
std::optional<std::size_t> heapBytesInUse();

/// What the preloaded allocation hooks count, when they are in this process.
struct HeapHookSample {
  std::size_t live_bytes = 0;
  std::size_t peak_bytes = 0;  ///< since the last resetHeapPeak()
  std::uint64_t allocations = 0;
};

/// The hooks' counters, or empty when they are not preloaded.
std::optional<HeapHookSample> heapHookSample();

/// Starts a new peak window: the peak becomes the current live count. No-op without the hooks.
void resetHeapPeak();

/// "hooks", "mallinfo2" or "none": which probe heapBytesInUse answers from.
std::string heapProbeName();

}  // namespace collido
