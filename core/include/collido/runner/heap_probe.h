#pragma once

#include <cstddef>
#include <optional>

namespace collido {

/// Bytes the C heap currently has handed out (glibc mallinfo2: arena plus mmapped chunks). It
/// counts every allocation of the process, engines' included, so the difference around a build
/// measures what the build kept, independently of what the backend says. Empty when the probe
/// does not work here (e.g. under AddressSanitizer, whose allocator glibc does not see).
std::optional<std::size_t> heapBytesInUse();

}  // namespace collido
