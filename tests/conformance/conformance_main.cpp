// collido_conformance: the plugin conformance kit.
//   collido_conformance --plugin=PATH.so [--plugin=...] [--variant='NAME[key=value;...]']
//                       [--expectations-dir=DIR] [--write-expectations-dir=DIR] [--scenes-dir=DIR]
//                       [--oracle-cache=DIR] [--fill-oracle-cache=DIR]
//                       [--skip-scenes=STEM,STEM...] [--progress] [GoogleTest flags]
// --progress replaces GoogleTest's output with one line per check as it ends ("[3/40] check:
// pass"), which collido conformance shows while the kit runs.
// Every variant of every plugin given is run through the whole suite (conformance_test.cpp).
// --skip-scenes leaves bundled scenes out (the sanitizer build leaves the heaviest ones to the
// Release run: tests/conformance/CMakeLists.txt).
// The exact oracle's answers are most of a run's time; CTest runs one plugin first with
// --fill-oracle-cache (written at the end) and the others with --oracle-cache (read for the
// identical scenes, the rest computed), so each scene's are computed once. Both together: the
// filling run starts from another store (the sanitizer build's, from the Release build's).
// Scenes load when a test first needs them, so a listing or the interface tests alone load none.
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <collido/host/install_layout.h>
#include <collido/runner/runner.h>

#include "conformance_target.h"
#include "scene_cases.h"

namespace collido::conformance {

std::vector<Target>& targets() {
  static std::vector<Target> list;
  return list;
}

KitSettings& settings() {
  static KitSettings values;
  return values;
}

std::string gtestName(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0) c = '_';
  }
  return out;
}

namespace {

// One line per finished check on stdout: "[done/total] suite.check: pass|FAIL|skip".
class ProgressPrinter final : public ::testing::EmptyTestEventListener {
 public:
  void OnTestProgramStart(const ::testing::UnitTest& unit) override {
    total_ = unit.test_to_run_count();
  }
  void OnTestEnd(const ::testing::TestInfo& test) override {
    const ::testing::TestResult& result = *test.result();
    const char* outcome = result.Skipped() ? "skip" : (result.Failed() ? "FAIL" : "pass");
    std::cout << "[" << ++done_ << "/" << total_ << "] " << test.test_suite_name() << "."
              << test.name() << ": " << outcome << std::endl;
  }

 private:
  int total_ = 0;
  int done_ = 0;
};

bool takeValue(const char* arg, const char* flag, std::string& out) {
  const std::size_t n = std::strlen(flag);
  if (std::strncmp(arg, flag, n) != 0 || arg[n] != '=') return false;
  out = arg + n + 1;
  return true;
}

}  // namespace
}  // namespace collido::conformance

int main(int argc, char** argv) {
  using namespace collido::conformance;
  std::vector<std::string> plugins;
  std::string only_variant;
  std::string oracle_cache;
  std::string fill_oracle_cache;
  std::set<std::string> skipped_scenes;
  bool progress = false;
  // Installed, the kit reads the installed scenes and expectations; in the build tree, the
  // source's.
  if (const std::string installed = collido::installedDataDirectory(); !installed.empty()) {
    settings().expectations_dir = installed + "/conformance/expectations";
    settings().scenes_dir = installed + "/scenes";
  } else {
    settings().expectations_dir = COLLIDO_SOURCE_DIR "/tests/conformance/expectations";
    settings().scenes_dir = COLLIDO_SOURCE_DIR "/scenes";
  }
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    std::string value;
    if (takeValue(argv[i], "--plugin", value)) {
      plugins.push_back(value);
    } else if (takeValue(argv[i], "--variant", value)) {
      only_variant = value;
    } else if (takeValue(argv[i], "--expectations-dir", value)) {
      settings().expectations_dir = value;
    } else if (takeValue(argv[i], "--write-expectations-dir", value)) {
      settings().write_expectations_dir = value;
    } else if (takeValue(argv[i], "--scenes-dir", value)) {
      settings().scenes_dir = value;
    } else if (takeValue(argv[i], "--oracle-cache", value)) {
      oracle_cache = value;
    } else if (takeValue(argv[i], "--fill-oracle-cache", value)) {
      fill_oracle_cache = value;
    } else if (std::strcmp(argv[i], "--progress") == 0) {
      progress = true;
    } else if (takeValue(argv[i], "--skip-scenes", value)) {
      std::stringstream names(value);
      for (std::string name; std::getline(names, name, ',');) {
        if (!name.empty()) skipped_scenes.insert(name);
      }
    } else {
      rest.push_back(argv[i]);
    }
  }
  if (plugins.empty()) {
    std::cerr << "collido_conformance: give at least one --plugin=PATH\n";
    return 2;
  }
  // --variant='name[key=value;...]': one variant, with options.
  std::map<std::string, std::string> variant_options;
  if (!only_variant.empty()) {
    collido::Result<std::pair<std::string, std::map<std::string, std::string>>> parsed =
        collido::parseBackendText(only_variant);
    if (!parsed.ok()) {
      std::cerr << "collido_conformance: --variant: " << parsed.status().message() << "\n";
      return 2;
    }
    only_variant = parsed.value().first;
    variant_options = parsed.value().second;
  }
  for (const std::string& path : plugins) {
    collido::Result<std::shared_ptr<collido::PluginLibrary>> library =
        collido::PluginLibrary::open(path);
    if (!library.ok()) {
      std::cerr << "collido_conformance: " << library.status().message() << "\n";
      return 2;
    }
    for (const collido::VariantInfo& v : library.value()->variants()) {
      if (!only_variant.empty() && v.name != only_variant) continue;
      targets().push_back(Target{library.value(), v.name, gtestName(v.name), variant_options});
    }
  }
  if (targets().empty()) {
    std::cerr << "collido_conformance: no variant '" << only_variant << "' in the plugins given\n";
    return 2;
  }
  if (!fill_oracle_cache.empty()) {
    // Answers left by an earlier build (another oracle) must not outlive a failed fill.
    std::error_code ec;
    std::filesystem::remove_all(fill_oracle_cache, ec);
  }
  // The scenes' solved placements are kept beside the oracle's answers: the filling run solves
  // them, the other plugins' runs read them.
  const std::string store = !fill_oracle_cache.empty() ? fill_oracle_cache : oracle_cache;
  if (collido::Status s = loadSceneCases(settings().scenes_dir, skipped_scenes,
                                         store.empty() ? "" : store + "/placements", oracle_cache);
      !s.ok()) {
    std::cerr << "collido_conformance: " << s.message() << "\n";
    return 2;
  }
  int rest_count = static_cast<int>(rest.size());
  rest.push_back(nullptr);  // argv[argc] is null, and GoogleTest moves it along with the flags
  ::testing::InitGoogleTest(&rest_count, rest.data());
  if (progress) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new ProgressPrinter);  // GoogleTest owns it
  }
  const int failed = RUN_ALL_TESTS();
  if (!fill_oracle_cache.empty()) {
    if (collido::Status s = storeOracleAnswers(fill_oracle_cache); !s.ok()) {
      std::cerr << "collido_conformance: " << s.message() << "\n";
      return 1;
    }
  }
  return failed;
}
