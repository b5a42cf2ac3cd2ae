// A plugin file that misbehaves while it is loaded, before the host can read anything from it:
// built as libcollido_plugin_crash_on_load.so (SIGSEGV in a static constructor) and
// libcollido_plugin_hang_on_load.so (a static constructor that never returns), into a folder of
// their own that only the test naming it loads.
#include <chrono>
#include <csignal>
#include <thread>

namespace {

__attribute__((constructor)) void misbehaveWhileLoading() {
#if defined(COLLIDO_TRAP_CRASH)
  std::signal(SIGSEGV, SIG_DFL);  // also under a sanitizer's handler
  std::raise(SIGSEGV);
#elif defined(COLLIDO_TRAP_HANG)
  for (;;)
    std::this_thread::sleep_for(std::chrono::seconds(1));
#else
#error "build with COLLIDO_TRAP_CRASH or COLLIDO_TRAP_HANG"
#endif
}

}  // namespace
