#include <filesystem>

#include "commands.h"

namespace collido::cli {

std::string thisExecutable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : self.string();
}

std::vector<std::string> pluginArguments(const PluginOptions& plugins) {
  std::vector<std::string> args;
  for (const std::string& path : plugins.paths) {
    args.push_back("--plugin");
    args.push_back(std::filesystem::absolute(path).string());
  }
  if (plugins.no_defaults) args.push_back("--no-default-plugins");
  return args;
}

}  // namespace collido::cli
