// Surface files: explicit and generated NURBS surfaces load; bad ones are refused with the file,
// the JSON path and the problem.
#include <gtest/gtest.h>

#include <collido/nurbs/surface_generators.h>
#include <collido/scene/surface_file.h>

#include "support/test_paths.h"

namespace collido {
namespace {

constexpr const char* kExplicit = R"({"surfaces": [
  {"name": "flat", "degree_u": 1, "degree_v": 1, "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1],
   "control": [[[0, 0, 0], [0, 1, 0, 2.0]], [[1, 0, 0], [1, 1, 0]]]},
  {"name": "zone", "generator": "sphere_zone", "centre": [0, 0, 3], "radius": 0.5}]})";

bool refused(const std::string& text, const std::vector<std::string>& words) {
  const Result<std::vector<NamedSurface>> r = parseSurfaces(text, "bad.json");
  if (r.ok()) return false;
  for (const std::string& w : words) {
    if (r.status().message().find(w) == std::string::npos) {
      ADD_FAILURE() << "'" << w << "' not in: " << r.status().message();
      return false;
    }
  }
  return true;
}

TEST(SurfaceFile, ExplicitAndGeneratedSurfacesLoad) {
  const Result<std::vector<NamedSurface>> r = parseSurfaces(kExplicit, "ok.json");
  ASSERT_TRUE(r.ok()) << r.status().message();
  ASSERT_EQ(r.value().size(), 2u);
  const nurbs::NurbsSurface& flat = r.value()[0].surface;
  EXPECT_EQ(flat.count_u, 2);
  EXPECT_EQ(flat.count_v, 2);
  EXPECT_EQ(flat.weight(0, 1), 2.0);
  EXPECT_TRUE(flat.point(0, 1).isApprox(Eigen::Vector3d(0, 1, 0)));
  const nurbs::NurbsSurface expected = nurbs::sphereZone(Eigen::Vector3d(0, 0, 3), 0.5, 0.0);
  EXPECT_EQ(r.value()[1].surface.control, expected.control);
}

TEST(SurfaceFile, EveryBundledSurfaceFileLoads) {
  for (const char* name : {"sphere_zones", "saddle_cap", "wavy_sheets", "blades", "touching_zones",
                           "explicit_bicubic"}) {
    const Result<std::vector<NamedSurface>> r =
        loadSurfaces(test::sourcePath(std::string("scenes/surfaces/") + name + ".json"));
    EXPECT_TRUE(r.ok()) << name << ": " << r.status().message();
  }
}

TEST(SurfaceFile, BadSurfacesAreNamed) {
  // A weight <= 0, with its place in the file.
  std::string text = kExplicit;
  text.replace(text.find("2.0]"), 3, "-1");
  EXPECT_TRUE(refused(text, {"bad.json", "/surfaces/0/control/0/1/3", "weight must be > 0"}));
  // Unclamped knots: the surface's own check, at the surface.
  text = kExplicit;
  text.replace(text.find("[0, 0, 1, 1], \"knots_v\""), 12, "[0, 0.5, 1, 1]");
  EXPECT_TRUE(refused(text, {"/surfaces/0", "knots_u: not clamped"}));
  // Rows of different lengths.
  text = kExplicit;
  text.replace(text.find("[[1, 0, 0], [1, 1, 0]]"), 22, "[[1, 0, 0]]");
  EXPECT_TRUE(refused(text, {"/surfaces/0/control/1", "a row of 1 points; row 0 has 2"}));
  EXPECT_TRUE(refused(R"({"surfaces": [{"name": "x", "generator": "torus"}]})",
                      {"/surfaces/0/generator", "unknown surface generator 'torus'"}));
  EXPECT_TRUE(refused(
      R"({"surfaces": [{"name": "x", "generator": "saddle"}, {"name": "x", "generator": "saddle"}]})",
      {"/surfaces/1/name", "duplicate surface name 'x'"}));
  EXPECT_TRUE(refused(R"({"surfaces": [{"name": "x", "generator": "saddle", "half": -1}]})",
                      {"/surfaces/0", "half must be > 0"}));
  EXPECT_TRUE(refused(R"({"surfaces": [{"name": "x", "degree_u": 3}]})",
                      {"/surfaces/0", "missing 'degree_v'"}));
  EXPECT_TRUE(refused(R"({"surfaces": []})", {"/surfaces", "no surfaces"}));
  EXPECT_TRUE(refused(R"({"surfaces": [}")", {"bad.json", "not valid JSON"}));
  EXPECT_FALSE(loadSurfaces("/no/such/surfaces.json").ok());
}

}  // namespace
}  // namespace collido
