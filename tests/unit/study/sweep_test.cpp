// Sweep files: what a valid file gives, and that every error names the file's label, the JSON
// pointer of the offending value and the problem.
#include <collido/study/sweep.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

constexpr const char* kLabel = "sweeps/mine.json";

/// The error message of a sweep that must be refused (empty, after a failure, when accepted).
std::string errorOf(const std::string& text) {
  const Result<Sweep> sweep = parseSweep(text, kLabel);
  if (sweep.ok()) {
    ADD_FAILURE() << "accepted: " << text;
    return "";
  }
  EXPECT_EQ(sweep.status().code(), StatusCode::kInvalidArgument);
  return sweep.status().message();
}

/// Asserts the message starts with the label and the pointer, and mentions `problem`.
void expectError(const std::string& text, const std::string& pointer, const std::string& problem) {
  SCOPED_TRACE(text);
  const std::string message = errorOf(text);
  EXPECT_EQ(message.rfind(std::string(kLabel) + ": " + pointer + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
}

TEST(Sweep, ValidFileGivesEveryList) {
  const Result<Sweep> parsed = parseSweep(R"({
    "comment": "a sweep",
    "backends": ["fcl:obb",
                 {"variant": "obbtree", "options": {"max_leaf_triangles": [1, 4],
                                                    "split": "median",
                                                    "margin": [0.25, true]}}],
    "resolutions": [1, 0.5],
    "needs": ["declared", "every"],
    "limits": [0, 16],
    "repetitions": 3,
    "field": {"ours": "fcl"},
    "timeout_s": 2.5})",
                                          kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  const Sweep& sweep = parsed.value();
  ASSERT_EQ(sweep.backends.size(), 2u);
  EXPECT_EQ(sweep.backends[0].variant, "fcl:obb");
  EXPECT_TRUE(sweep.backends[0].options.empty());
  EXPECT_EQ(sweep.backends[1].variant, "obbtree");
  ASSERT_EQ(sweep.backends[1].options.size(), 3u);
  // Options keep the order the file gives them in (the setting texts follow it).
  EXPECT_EQ(sweep.backends[1].options[0].first, "max_leaf_triangles");
  EXPECT_EQ(sweep.backends[1].options[0].second, (std::vector<std::string>{"1", "4"}));
  EXPECT_EQ(sweep.backends[1].options[1].first, "split");
  EXPECT_EQ(sweep.backends[1].options[1].second, (std::vector<std::string>{"median"}));
  EXPECT_EQ(sweep.backends[1].options[2].first, "margin");
  EXPECT_EQ(sweep.backends[1].options[2].second, (std::vector<std::string>{"0.25", "true"}));
  EXPECT_EQ(sweep.resolutions, (std::vector<double>{1.0, 0.5}));
  EXPECT_EQ(sweep.needs, (std::vector<NeedsMode>{NeedsMode::kDeclared, NeedsMode::kEvery}));
  EXPECT_EQ(sweep.limits, (std::vector<std::uint64_t>{0, 16}));
  EXPECT_EQ(sweep.repetitions, 3);
  EXPECT_EQ(sweep.timeout_s, 2.5);
  EXPECT_EQ(sweep.field.ours, "fcl");
  EXPECT_EQ(sweep.field.peer, "fcl:obb");
  EXPECT_EQ(sweep.backends[1].settings(),
            (std::vector<std::string>{"obbtree[max_leaf_triangles=1;split=median;margin=0.25]",
                                      "obbtree[max_leaf_triangles=1;split=median;margin=true]",
                                      "obbtree[max_leaf_triangles=4;split=median;margin=0.25]",
                                      "obbtree[max_leaf_triangles=4;split=median;margin=true]"}));
}

// Needs modes per scene, as resolutions: "*" for the scenes not named.
TEST(Sweep, NeedsPerScene) {
  const Result<Sweep> parsed = parseSweep(
      R"({"needs": {"*": ["declared"], "held": ["declared", "changed", "every"]}})", kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(parsed.value().needsOf("tori"), (std::vector<NeedsMode>{NeedsMode::kDeclared}));
  EXPECT_EQ(parsed.value().needsOf("held"),
            (std::vector<NeedsMode>{NeedsMode::kDeclared, NeedsMode::kChanged, NeedsMode::kEvery}));
}

TEST(Sweep, EmptyObjectKeepsTheDefaults) {
  const Result<Sweep> parsed = parseSweep("{}", kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_TRUE(parsed.value().backends.empty());
  EXPECT_EQ(parsed.value().resolutions, (std::vector<double>{1.0}));
  EXPECT_EQ(parsed.value().needs, (std::vector<NeedsMode>{NeedsMode::kDeclared}));
  EXPECT_EQ(parsed.value().limits, (std::vector<std::uint64_t>{0}));
  EXPECT_FALSE(parsed.value().repetitions.has_value());
  EXPECT_FALSE(parsed.value().timeout_s.has_value());
}

TEST(Sweep, OptionNumbersKeepTheirShortestForm) {
  const Result<Sweep> parsed = parseSweep(
      R"({"backends": [{"variant": "x", "options": {"a": [0.1, 2, -3, 1e-3, 2.5]}}]})", kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(parsed.value().backends[0].options[0].second,
            (std::vector<std::string>{"0.1", "2", "-3", "0.001", "2.5"}));
}

TEST(Sweep, ABackendMayBeKeptToSomeScenes) {
  const Result<Sweep> parsed = parseSweep(
      R"({"backends": ["obbtree", {"variant": "fcl:obb", "options": {"rebuild": [true]},
                                   "scenes": ["deforming_tori", "sheet_over_bunny"]}]})",
      kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_TRUE(parsed.value().backends[0].scenes.empty());
  EXPECT_EQ(parsed.value().backends[1].scenes,
            (std::vector<std::string>{"deforming_tori", "sheet_over_bunny"}));
}

TEST(Sweep, ABackendMayBeOptional) {
  const Result<Sweep> parsed =
      parseSweep(R"({"backends": ["obbtree", {"variant": "cgal", "optional": true}]})", kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_FALSE(parsed.value().backends[0].optional);
  EXPECT_TRUE(parsed.value().backends[1].optional);
  expectError(R"({"backends": [{"variant": "x", "optional": "yes"}]})", "/backends/0/optional",
              "expected true or false");
}

TEST(Sweep, ErrorsNameLabelPointerAndProblem) {
  expectError(R"({"backends": [{"variant": "x", "scenes": []}]})", "/backends/0/scenes",
              "at least one entry");
  expectError(R"({"backends": [{"variant": "x", "scenes": ["a", 3]}]})", "/backends/0/scenes/1",
              "expected a scene name");
  expectError(R"({"backends": [{"variant": "x", "scenes": [""]}]})", "/backends/0/scenes/0",
              "expected a scene name");
  expectError("[1]", "/", "expected an object");
  expectError(R"({"backend": []})", "/", "unknown key 'backend'");
  expectError(R"({"backends": []})", "/backends", "at least one entry");
  expectError(R"({"backends": "obbtree"})", "/backends", "expected an array");
  expectError(R"({"backends": [3]})", "/backends/0", "expected an object");
  expectError(R"({"backends": ["obbtree", {"options": {}}]})", "/backends/1", "missing 'variant'");
  expectError(R"({"backends": [{"variant": ""}]})", "/backends/0/variant", "must not be empty");
  expectError(R"({"backends": [{"variant": "x", "opts": {}}]})", "/backends/0",
              "unknown key 'opts'");
  expectError(R"({"backends": [{"variant": "x", "options": [1]}]})", "/backends/0/options",
              "expected an object");
  expectError(R"({"backends": ["a", {"variant": "x", "options": {"margin": []}}]})",
              "/backends/1/options/margin", "at least one entry");
  expectError(R"({"backends": ["a", {"variant": "x", "options": {"margin": {"v": 1}}}]})",
              "/backends/1/options/margin", "expected a number, string or boolean");
  expectError(R"({"backends": [{"variant": "x", "options": {"margin": [1, null]}}]})",
              "/backends/0/options/margin/1", "expected a number, string or boolean");
  expectError(R"({"resolutions": []})", "/resolutions", "at least one entry");
  expectError(R"({"resolutions": [1, 0]})", "/resolutions/1", "positive number");
  expectError(R"({"resolutions": [-0.5]})", "/resolutions/0", "positive number");
  expectError(R"({"resolutions": ["1"]})", "/resolutions/0", "positive number");
  expectError(R"({"needs": []})", "/needs", "at least one entry");
  expectError(R"({"needs": ["declared", "all"]})", "/needs/1",
              R"("declared", "changed" or "every")");
  expectError(R"({"needs": [1]})", "/needs/0", R"("declared", "changed" or "every")");
  expectError(R"({"needs": {"tori": ["cold"]}})", "/needs/tori/0", R"("changed" or "every")");
  expectError(R"({"needs": {"*": []}})", "/needs/*", "at least one entry");
  expectError(R"({"limits": []})", "/limits", "at least one entry");
  expectError(R"({"limits": [0, -1]})", "/limits/1", "whole number >= 0");
  expectError(R"({"limits": [2.5]})", "/limits/0", "whole number >= 0");
  expectError(R"({"limits": ["8"]})", "/limits/0", "whole number >= 0");
  expectError(R"({"repetitions": 0})", "/repetitions", "from 1 to 1000000");
  expectError(R"({"repetitions": 2.5})", "/repetitions", "from 1 to 1000000");
  expectError(R"({"repetitions": 1000001})", "/repetitions", "from 1 to 1000000");
  expectError(R"({"protocol": "shuffled"})", "/protocol", R"("repeated" or "cycled")");
  expectError(R"({"protocol": 1})", "/protocol", R"("repeated" or "cycled")");
  expectError(R"({"field": {"ours": ""}})", "/field/ours", "expected a backend name");
  expectError(R"({"field": {"theirs": "x"}})", "/field", "unknown key 'theirs'");
  expectError(R"({"timeout_s": 0})", "/timeout_s", "positive number of seconds");
  expectError(R"({"timeout_s": -1})", "/timeout_s", "positive number of seconds");
  expectError(R"({"timeout_s": "60"})", "/timeout_s", "positive number of seconds");
}

// As in scene files, a repeated key is refused rather than the last one silently counting.
TEST(Sweep, SurfaceAndFrepEntriesNameSettingsAndGrids) {
  const Result<Sweep> parsed = parseSweep(R"({
    "surfaces": {"backends": ["nurbs:hull", "obbtree[max_leaf_triangles=4]"],
                 "tessellations": [8, 32]},
    "frep": {"resolutions": [16]}})",
                                          kLabel);
  ASSERT_TRUE(parsed.ok()) << parsed.status().message();
  EXPECT_EQ(parsed.value().surfaces.backends,
            (std::vector<std::string>{"nurbs:hull", "obbtree[max_leaf_triangles=4]"}));
  EXPECT_EQ(parsed.value().surfaces.grid, (std::vector<int>{8, 32}));
  EXPECT_TRUE(parsed.value().frep.backends.empty());  // the study's mesh settings
  EXPECT_EQ(parsed.value().frep.grid, (std::vector<int>{16}));
  const Result<Sweep> defaults = parseSweep("{}", kLabel);
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(defaults.value().surfaces.grid, (std::vector<int>{8, 32, 128}));
  EXPECT_EQ(defaults.value().frep.grid, (std::vector<int>{16, 32, 64}));

  expectError(R"({"surfaces": {"tessellations": [0]}})", "/surfaces/tessellations/0",
              "whole number from 1 to 1024");
  expectError(R"({"frep": {"resolutions": [1]}})", "/frep/resolutions/0",
              "whole number from 2 to 1024");
  expectError(R"({"frep": {"backends": [3]}})", "/frep/backends/0", "backend setting");
  expectError(R"({"surfaces": {"segments": [8]}})", "/surfaces", "unknown key 'segments'");
  expectError(R"({"frep": []})", "/frep", "expected an object");
}

TEST(Sweep, ARepeatedKeyIsRefused) {
  expectError(R"({"backends": ["obbtree"], "backends": ["ode"]})", "/backends",
              "duplicate key 'backends'");
  expectError(R"({"backends": [{"variant": "x", "options": {"a": [1], "a": [2]}}]})",
              "/backends/0/options/a", "duplicate key 'a'");
}

TEST(Sweep, InvalidJsonNamesTheLabel) {
  const std::string message = errorOf(R"({"backends": [)");
  EXPECT_EQ(message.rfind(std::string(kLabel) + ": not valid JSON", 0), 0u) << message;
}

TEST(Sweep, LoadSweepNamesTheFile) {
  const std::string dir = test::makeTempDirectory("sweep");
  const std::string path = dir + "/sweep.json";
  test::writeFile(path, R"({"limits": [-4]})");
  const Result<Sweep> bad = loadSweep(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().message().rfind(path + ": /limits/0: ", 0), 0u) << bad.status().message();
  test::writeFile(path, R"({"limits": [4]})");
  const Result<Sweep> good = loadSweep(path);
  ASSERT_TRUE(good.ok()) << good.status().message();
  EXPECT_EQ(good.value().limits, (std::vector<std::uint64_t>{4}));
  const Result<Sweep> missing = loadSweep(dir + "/none.json");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find(dir + "/none.json"), std::string::npos);
}

TEST(SweepBackend, SettingsAreTheCartesianProductInOptionOrder) {
  EXPECT_EQ((SweepBackend{"obbtree", {}, {}}.settings()), (std::vector<std::string>{"obbtree"}));
  const SweepBackend backend{"obbtree", {{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}}, {}};
  EXPECT_EQ(backend.settings(),
            (std::vector<std::string>{"obbtree[a=1;b=x]", "obbtree[a=1;b=y]", "obbtree[a=1;b=z]",
                                      "obbtree[a=2;b=x]", "obbtree[a=2;b=y]", "obbtree[a=2;b=z]"}));
  const SweepBackend reversed{"fcl:obb", {{"b", {"x"}}, {"a", {"1"}}}, {}};
  EXPECT_EQ(reversed.settings(), (std::vector<std::string>{"fcl:obb[b=x;a=1]"}));
}

TEST(NeedsMode, NamesRoundTrip) {
  for (const NeedsMode mode : {NeedsMode::kDeclared, NeedsMode::kChanged, NeedsMode::kEvery})
    EXPECT_EQ(parseNeedsMode(needsModeName(mode)), mode);
  EXPECT_STREQ(needsModeName(NeedsMode::kDeclared), "declared");
  EXPECT_STREQ(needsModeName(NeedsMode::kChanged), "changed");
  EXPECT_STREQ(needsModeName(NeedsMode::kEvery), "every");
  EXPECT_FALSE(parseNeedsMode("Every").has_value());
  EXPECT_FALSE(parseNeedsMode("").has_value());
}

}  // namespace
}  // namespace collido::study
