// STEP and IGES import through OpenCASCADE (backends/occt/tools): two unit spheres written by the
// CAD kernel's own writers, centres 3 apart, come back as surfaces whose certified distance is 1;
// bad files are refused with the file named.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include <collido/nurbs/surface_distance.h>
#include <collido/scene/surface_file.h>

#include "support/test_paths.h"

namespace collido::test {
namespace {

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs an OpenCASCADE tool. Under AddressSanitizer its leak check is off in that process only:
// OpenCASCADE's data exchange keeps session objects alive at exit (about 3 KiB in 159 blocks
// per run, all allocated inside libTKernel's memory manager), which are not ours to fix; this
// test's own process keeps the check.
Outcome runCommand(const std::string& command) {
  Outcome out;
  const std::string line = "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " + command + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(line.c_str(), "r"), pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get()) != nullptr)
    out.output += buffer.data();
  const int status = pclose(pipe.release());
  out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

class CadImport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = makeTempDirectory("cad_import");
    const Outcome written = runCommand(std::string(COLLIDO_CAD_FIXTURE) + " '" + directory_ + "'");
    ASSERT_EQ(written.exit_code, 0) << written.output;
  }
  static std::string importer() { return COLLIDO_CAD_IMPORT; }
  static std::string directory_;
};
std::string CadImport::directory_;

void expectSpheresOneApart(const std::string& surface_file) {
  Result<std::vector<NamedSurface>> surfaces = loadSurfaces(surface_file);
  ASSERT_TRUE(surfaces.ok()) << surfaces.status().message();
  ASSERT_EQ(surfaces.value().size(), 2u);
  nurbs::SurfaceDistanceOptions options;
  options.tolerance = 1e-9;
  const nurbs::SurfaceDistance d =
      nurbs::minimumDistance(surfaces.value()[0].surface, surfaces.value()[1].surface, options);
  ASSERT_TRUE(d.converged);
  EXPECT_LE(d.lower, 1.0 + 1e-12);
  EXPECT_GE(d.upper, 1.0 - 1e-12);
  EXPECT_NEAR(d.point_a.norm(), 1.0, 1e-9);  // on the first sphere, about the origin
  EXPECT_NEAR(d.point_a.x(), 1.0, 1e-4);     // facing the second
}

TEST_F(CadImport, StepSpheresComeBackOneApart) {
  const std::string out = directory_ + "/step.json";
  const Outcome imported =
      runCommand(importer() + " '" + directory_ + "/two_spheres.step' -o '" + out + "'");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  EXPECT_NE(imported.output.find("Geom_SphericalSurface"), std::string::npos) << imported.output;
  expectSpheresOneApart(out);
}

TEST_F(CadImport, IgesSpheresComeBackOneApart) {
  const std::string out = directory_ + "/iges.json";
  const Outcome imported =
      runCommand(importer() + " '" + directory_ + "/two_spheres.iges' -o '" + out + "'");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  expectSpheresOneApart(out);
}

TEST_F(CadImport, ChosenFacesOnly) {
  const std::string out = directory_ + "/one.json";
  const Outcome imported =
      runCommand(importer() + " '" + directory_ + "/two_spheres.step' --faces 1 -o '" + out + "'");
  ASSERT_EQ(imported.exit_code, 0) << imported.output;
  Result<std::vector<NamedSurface>> surfaces = loadSurfaces(out);
  ASSERT_TRUE(surfaces.ok()) << surfaces.status().message();
  ASSERT_EQ(surfaces.value().size(), 1u);
  EXPECT_EQ(surfaces.value()[0].name, "two_spheres_face1");
  const Outcome missing =
      runCommand(importer() + " '" + directory_ + "/two_spheres.step' --faces 7 -o '" + out + "'");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("no face 7"), std::string::npos) << missing.output;
}

TEST_F(CadImport, BadFilesAreRefusedNamingTheFile) {
  const std::string out = directory_ + "/bad.json";
  const Outcome missing = runCommand(importer() + " '" + directory_ + "/nope.step' -o " + out);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("nope.step: file not found"), std::string::npos) << missing.output;
  writeFile(directory_ + "/garbage.step", "this is not ISO 10303-21\n");
  const Outcome garbage = runCommand(importer() + " '" + directory_ + "/garbage.step' -o " + out);
  EXPECT_EQ(garbage.exit_code, 2);
  EXPECT_NE(garbage.output.find("garbage.step: not a readable STEP file"), std::string::npos)
      << garbage.output;
  writeFile(directory_ + "/part.obj", "v 0 0 0\n");
  const Outcome other = runCommand(importer() + " '" + directory_ + "/part.obj' -o " + out);
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.output.find("is not .step, .stp, .iges or .igs"), std::string::npos)
      << other.output;
}

}  // namespace
}  // namespace collido::test
