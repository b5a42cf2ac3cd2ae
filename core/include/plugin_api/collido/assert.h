#pragma once

namespace collido {

/// Called when a COLLIDO_ASSERT fails; the default prints the message and aborts.
using AssertHandler = void (*)(const char* expression, const char* message, const char* file,
                               int line);

/// Replaces the assert handler (e.g. to throw in a test); returns the previous one.
AssertHandler setAssertHandler(AssertHandler handler);

namespace detail {
[[noreturn]] void assertFailed(const char* expression, const char* message, const char* file,
                               int line);
}  // namespace detail

}  // namespace collido

/// Checks a programming invariant in every build type; failures go to the assert handler.
#define COLLIDO_ASSERT(condition, message)                                        \
  do {                                                                            \
    if (!(condition)) {                                                           \
      ::collido::detail::assertFailed(#condition, (message), __FILE__, __LINE__); \
    }                                                                             \
  } while (false)
