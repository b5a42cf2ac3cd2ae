// Resident memory from /proc/self/status (VmRSS now, VmHWM the peak), with the peak reset
// through /proc/self/clear_refs (Linux 4.0 and later).
#include <collido/study/resident_memory.h>

#include <malloc.h>

#include <fstream>
#include <string>

namespace collido::study {
namespace {

// A "Name:   123 kB" line of /proc/self/status, in bytes.
std::optional<std::size_t> statusBytes(const std::string& name) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(name + ":", 0) != 0) continue;
    const std::size_t digits = line.find_first_of("0123456789");
    if (digits == std::string::npos) return std::nullopt;
    return static_cast<std::size_t>(std::stoull(line.substr(digits))) * 1024;
  }
  return std::nullopt;
}

}  // namespace

ResidentPeak::ResidentPeak() {
  // Heap the worker freed (parsing, the oracle's work) would otherwise stay resident and be
  // reused by the backend without showing as growth.
  malloc_trim(0);
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  if (!clear) return;
  baseline_ = statusBytes("VmRSS");
}

std::optional<std::size_t> ResidentPeak::addedBytes() const {
  if (!baseline_) return std::nullopt;
  const std::optional<std::size_t> peak = statusBytes("VmHWM");
  if (!peak) return std::nullopt;
  return *peak > *baseline_ ? *peak - *baseline_ : 0;
}

}  // namespace collido::study
