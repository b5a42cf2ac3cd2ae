#include <collido/runner/heap_probe.h>

#include <malloc.h>

namespace collido {

std::optional<std::size_t> heapBytesInUse() {
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

}  // namespace collido
