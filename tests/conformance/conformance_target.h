#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <collido/host/plugin_library.h>

namespace collido::conformance {

/// One backend variant under test.
struct Target {
  std::shared_ptr<PluginLibrary> library;
  std::string variant;
  std::string test_name;  ///< the variant as a GoogleTest name ("fcl_obb")
  std::map<std::string, std::string> options = {};  ///< from --variant 'name[key=value;...]'
};

/// Where the kit reads and writes, from the command line.
struct KitSettings {
  std::string expectations_dir;        ///< committed expectation files, one per variant
  std::string write_expectations_dir;  ///< when set, measured counts are written here
  std::string scenes_dir;              ///< bundled scenes to run
};

/// `text` as a GoogleTest name: every character but letters and digits becomes '_'.
std::string gtestName(const std::string& text);

/// The targets and settings, filled by main() before GoogleTest registers the tests.
std::vector<Target>& targets();
KitSettings& settings();

}  // namespace collido::conformance
