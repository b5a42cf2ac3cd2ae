// Malformed FRep files: each refusal names the file, the JSON path and the problem.
#include <string>

#include <gtest/gtest.h>

#include <collido/scene/frep_file.h>

#include "rejection.h"

namespace collido {
namespace {

constexpr const char* kFile = "case.json";

std::string withSolid(const std::string& solid) {
  return R"({"solids": [{"name": "a", "solid": )" + solid +
         R"(}, {"name": "b", "solid": {"type": "sphere", "radius": 1}}]})";
}

::testing::AssertionResult refused(const std::string& text,
                                   std::initializer_list<std::string> words) {
  const Result<FrepFile> file = parseFrepFile(text, kFile);
  if (file.ok()) return ::testing::AssertionFailure() << "accepted: " << text;
  return test::hasCodeAndWords(file.status(), StatusCode::kInvalidArgument, words);
}

TEST(FrepFileBadInput, BrokenJson) {
  EXPECT_TRUE(refused("{\"solids\": [", {kFile}));
}

TEST(FrepFileBadInput, MissingSolidsAndUnknownKeys) {
  EXPECT_TRUE(refused("{}", {kFile, "missing 'solids'"}));
  EXPECT_TRUE(refused(R"({"solids": [], "speed": 1})", {kFile, "unknown key 'speed'"}));
  EXPECT_TRUE(refused(R"({"solids": []})", {kFile, "/solids", "no solids"}));
}

TEST(FrepFileBadInput, UnknownTypeNamesThePath) {
  EXPECT_TRUE(refused(withSolid(R"({"type": "blob"})"),
                      {kFile, "/solids/0/solid/type", "unknown solid type 'blob'"}));
}

TEST(FrepFileBadInput, NonFiniteAndNegativeParameters) {
  EXPECT_TRUE(refused(withSolid(R"({"type": "sphere", "radius": -1})"),
                      {kFile, "/solids/0/solid", "radius must be > 0"}));
  EXPECT_TRUE(refused(withSolid(R"({"type": "sphere", "radius": "big"})"),
                      {kFile, "/solids/0/solid/radius", "expected a number"}));
  EXPECT_TRUE(refused(withSolid(R"({"type": "torus", "major_radius": 1})"),
                      {kFile, "/solids/0/solid", "missing 'minor_radius'"}));
  EXPECT_TRUE(refused(
      withSolid(
          R"({"type": "superellipsoid", "radii": [1, 1, 1], "east_west": 9, "north_south": 1})"),
      {kFile, "/solids/0/solid", "exponents"}));
}

TEST(FrepFileBadInput, NestedOperandErrorsNameTheirPath) {
  EXPECT_TRUE(refused(
      withSolid(R"({"type": "union", "of": [{"type": "sphere", "radius": 1}, {"type": "cone"}]})"),
      {kFile, "/solids/0/solid/of/1", "missing 'half_angle_degrees'"}));
  EXPECT_TRUE(refused(withSolid(R"({"type": "union", "of": [], "blend": "soft"})"),
                      {kFile, "/solids/0/solid/of", "no operands"}));
  EXPECT_TRUE(refused(
      withSolid(R"({"type": "union", "of": [{"type": "sphere", "radius": 1}], "blend": "soft"})"),
      {kFile, "/solids/0/solid/blend", "unknown blend 'soft'"}));
}

TEST(FrepFileBadInput, AnimatedValuesAreCheckedAtEveryFrame) {
  // The morph parameter leaves [0, 1] at t = 1 only.
  const std::string text =
      R"({"frames": {"count": 3, "duration": 1}, "solids": [{"name": "a", "solid":
          {"type": "morph", "t": {"keys": [[0, 0], [1, 1.5]]},
           "from": {"type": "sphere", "radius": 1}, "to": {"type": "sphere", "radius": 2}}},
         {"name": "b", "solid": {"type": "sphere", "radius": 1}}]})";
  EXPECT_TRUE(refused(text, {kFile, "/solids/0/solid/t", "outside [0, 1]"}));
  EXPECT_TRUE(refused(
      withSolid(
          R"({"type": "offset", "solid": {"type": "sphere", "radius": 1}, "by": {"keys": [[1, 0], [0, 1]]}})"),
      {kFile, "/solids/0/solid/by/keys/1/0", "increase"}));
}

TEST(FrepFileBadInput, PairsNameKnownDistinctSolids) {
  const std::string solids =
      R"({"solids": [{"name": "a", "solid": {"type": "sphere", "radius": 1}},
                     {"name": "a", "solid": {"type": "sphere", "radius": 1}}]})";
  EXPECT_TRUE(refused(solids, {kFile, "/solids/1/name", "duplicate solid name 'a'"}));
  const std::string base =
      R"({"solids": [{"name": "a", "solid": {"type": "sphere", "radius": 1}},
                     {"name": "b", "solid": {"type": "sphere", "radius": 1}}], "pairs": )";
  EXPECT_TRUE(refused(base + R"([["a", "c"]]})", {kFile, "/pairs/0/1", "unknown solid 'c'"}));
  EXPECT_TRUE(refused(base + R"([["a", "a"]]})", {kFile, "/pairs/0", "itself"}));
  EXPECT_TRUE(
      refused(base + R"([["a", "b", "maybe"]]})", {kFile, "/pairs/0/2", "expected answer"}));
}

TEST(FrepFileBadInput, ProjectionOfAnUnboundedSolid) {
  EXPECT_TRUE(refused(
      withSolid(
          R"({"type": "project", "axis": "z", "solid": {"type": "half_space", "normal": [0, 0, 1]}})"),
      {kFile, "/solids/0/solid", "bounded along the projection axis"}));
}

TEST(FrepFileBadInput, MissingFileIsNamed) {
  const Result<FrepFile> file = loadFrepFile("/no/such/frep.json");
  ASSERT_FALSE(file.ok());
  EXPECT_TRUE(test::hasCodeAndWords(file.status(), StatusCode::kInvalidArgument,
                                    {"/no/such/frep.json", "FRep file not found"}));
}

TEST(FrepFile, AnimatedSolidsChangeWithTime) {
  const std::string text =
      R"({"frames": {"count": 3, "duration": 2}, "solids": [
           {"name": "a", "solid": {"type": "offset", "by": {"keys": [[0, 0], [2, 3]]},
                                   "solid": {"type": "sphere", "radius": 1}}},
           {"name": "b", "solid": {"type": "sphere", "centre": [5, 0, 0], "radius": 1}}],
          "pairs": [["a", "b", "separated"]]})";
  const Result<FrepFile> file = parseFrepFile(text, kFile);
  ASSERT_TRUE(file.ok()) << file.status().message();
  ASSERT_EQ(file.value().times.size(), 3U);
  EXPECT_DOUBLE_EQ(file.value().times[1], 1.0);
  EXPECT_TRUE(file.value().solids[0].animated);
  EXPECT_FALSE(file.value().solids[1].animated);
  // r^2 - |x|^2 + offset at the centre: 1 + 1.5 at t = 1.
  EXPECT_DOUBLE_EQ(file.value().solids[0].at(1.0)->value(Eigen::Vector3d::Zero()), 2.5);
  EXPECT_EQ(file.value().expected[0], "separated");
}

}  // namespace
}  // namespace collido
