#include <collido/host/install_layout.h>

#include <filesystem>
#include <system_error>

#include <collido/host/plugin_library.h>

namespace collido {
namespace {

// The same relative paths as the install rules (CMakeLists.txt, COLLIDO_INSTALL_*).
std::string installedFolder(const char* relative_to_prefix) {
  const std::string exe_dir = executableDirectory();
  if (exe_dir.empty()) return {};
  std::error_code ec;
  const std::filesystem::path folder = std::filesystem::path(exe_dir) / ".." / relative_to_prefix;
  if (!std::filesystem::is_directory(folder, ec)) return {};
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(folder, ec);
  return ec ? folder.string() : canonical.string();
}

}  // namespace

std::string installedDataDirectory() {
  return installedFolder("share/collido");
}

std::string installedLibraryDirectory() {
  return installedFolder("lib/collido");
}

}  // namespace collido
