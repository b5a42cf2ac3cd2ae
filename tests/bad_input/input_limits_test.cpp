// Input files are checked for kind and size before anything reads them: a device such as
// /dev/zero or an oversized (here sparse) file is refused at once, naming the file, instead of
// being read until memory runs out.
#include <collido/mesh/input_file.h>
#include <collido/mesh/mesh_io.h>
#include <collido/scene/scene.h>
#include <collido/study/sweep.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "bad_input/rejection.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using test::rejected;

/// Sets COLLIDO_MAX_INPUT_MB for one test and restores what was there.
class InputLimit {
 public:
  explicit InputLimit(const char* mebibytes) {
    if (const char* old = std::getenv(kName); old != nullptr) saved_ = old;
    setenv(kName, mebibytes, 1);
  }
  ~InputLimit() {
    if (saved_.empty()) {
      unsetenv(kName);
    } else {
      setenv(kName, saved_.c_str(), 1);
    }
  }
  InputLimit(const InputLimit&) = delete;
  InputLimit& operator=(const InputLimit&) = delete;

 private:
  static constexpr const char* kName = "COLLIDO_MAX_INPUT_MB";
  std::string saved_;
};

/// A sparse file of `bytes` bytes: no disk is used, yet its size is what a reader sees.
std::string sparseFile(const std::string& name, std::uintmax_t bytes) {
  const std::string path = test::makeTempDirectory("input_limits") + "/" + name;
  test::writeFile(path, "");
  std::filesystem::resize_file(path, bytes);
  return path;
}

// "/dev/zero: not a regular file (a device, pipe or socket), so not a mesh file"
TEST(InputLimits, DevicesAreRefusedBeforeReading) {
  EXPECT_TRUE(rejected(loadMesh("/dev/zero"), {"/dev/zero", "not a regular file", "mesh"}));
  EXPECT_TRUE(rejected(loadScene("/dev/zero"), {"/dev/zero", "not a regular file", "scene"}));
  EXPECT_TRUE(
      rejected(study::loadSweep("/dev/zero"), {"/dev/zero", "not a regular file", "sweep"}));
}

// "<dir>/huge.stl: the mesh file holds 3.0 MiB, more than the input limit of 2.0 MiB (raise it
//  with COLLIDO_MAX_INPUT_MB or collido --max-input-mb)"
TEST(InputLimits, AFileOverTheLimitIsRefusedNamingSizeAndLimit) {
  const InputLimit limit("2");
  EXPECT_EQ(inputLimitBytes(), 2u << 20u);
  const std::string mesh = sparseFile("huge.stl", 3u << 20u);
  EXPECT_TRUE(rejected(loadMesh(mesh),
                       {mesh, "3.0 MiB", "input limit of 2.0 MiB", "COLLIDO_MAX_INPUT_MB"}));
  const std::string scene = sparseFile("huge.json", 3u << 20u);
  EXPECT_TRUE(rejected(loadScene(scene), {scene, "scene file", "input limit"}));
  // At the limit is allowed: the sparse file of zeros then fails as a mesh, not on its size.
  const std::string at_limit = sparseFile("at_limit.stl", 2u << 20u);
  const Result<TriangleMesh> read = loadMesh(at_limit);
  ASSERT_FALSE(read.ok());
  EXPECT_EQ(read.status().message().find("input limit"), std::string::npos)
      << read.status().message();
}

TEST(InputLimits, AMalformedLimitKeepsTheDefault) {
  for (const char* text : {"0", "-5", "12abc", "", "99999999999999999999999"}) {
    const InputLimit limit(text);
    EXPECT_EQ(inputLimitBytes(), 1024u << 20u) << text;
  }
}

}  // namespace
}  // namespace collido
