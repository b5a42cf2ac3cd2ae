#pragma once

#include <stdint.h>  // NOLINT(modernize-deprecated-headers): also read as C

// The allocation hooks' C interface, looked up with dlsym in a process they were preloaded
// into (core/src/runner/heap_probe.cpp). Byte counts are malloc_usable_size sums.
#ifdef __cplusplus
extern "C" {
#endif

/// What the hooks have counted since the process started.
typedef struct CollidoHeapHookCounters {
  int64_t live_bytes;   /* bytes handed out and not yet freed */
  int64_t peak_bytes;   /* the most live_bytes reached since the last reset */
  uint64_t allocations; /* successful allocation calls */
} CollidoHeapHookCounters;

typedef CollidoHeapHookCounters (*CollidoHeapHooksRead)(void);
typedef void (*CollidoHeapHooksResetPeak)(void);

#ifdef __cplusplus
}
#endif
