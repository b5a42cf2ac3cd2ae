#include "support/test_paths.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

namespace collido::test {

std::string sourcePath(const std::string& relative) {
  return std::string(COLLIDO_SOURCE_DIR) + "/" + relative;
}

std::string pluginDirectory() {
  return COLLIDO_PLUGIN_DIR;
}

std::string makeTempDirectory(const std::string& hint) {
  namespace fs = std::filesystem;
  std::random_device device;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path dir =
        fs::temp_directory_path() / ("collido_" + hint + "_" + std::to_string(device()));
    if (fs::create_directory(dir)) return dir.string();
  }
  throw std::runtime_error("cannot create a temporary directory for " + hint);
}

void writeFile(const std::string& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << contents;
}

}  // namespace collido::test
