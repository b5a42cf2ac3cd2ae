// Whether the batched box test can run here: the AVX2 kernel (box_batch_avx2.cpp) needs both
// AVX2 and FMA.
#include "box_batch.h"

namespace collido::obbtree::detail {

bool vectorBoxTestsAvailable() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool available = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return available;
#else
  return false;
#endif
}

}  // namespace collido::obbtree::detail
