#include <collido/assert.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace collido {
namespace {

// The default handler is the one place library code writes to stderr: a broken invariant is about
// to abort the process, and the message is all that is left to explain it.
void printAndAbort(const char* expression, const char* message, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: COLLIDO_ASSERT(%s) failed: %s\n", file, line, expression, message);
  std::abort();
}

std::atomic<AssertHandler> g_handler{&printAndAbort};

}  // namespace

AssertHandler setAssertHandler(AssertHandler handler) {
  return g_handler.exchange(handler != nullptr ? handler : &printAndAbort);
}

namespace detail {

void assertFailed(const char* expression, const char* message, const char* file, int line) {
  g_handler.load()(expression, message, file, line);
  std::abort();  // a handler that returns must not let execution continue past the invariant
}

}  // namespace detail
}  // namespace collido
