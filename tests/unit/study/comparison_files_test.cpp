// Joining a surface or FRep file's combinations into the document its command would write.
#include <collido/study/comparison_files.h>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

CombinationResult part(InputKind kind, const std::string& backend, const Json& comparison) {
  CombinationResult r;
  r.combination.kind = kind;
  r.combination.scene_path = "/data/scenes/surfaces/blades.json";
  r.combination.scene_name = "blades";
  r.combination.backend = backend;
  r.combination.grid = {8, 32};
  r.comparison = comparison;
  return r;
}

TEST(ComparisonDocuments, SeedRowsThenEveryBackendsRowsAndTheWorkersThatDied) {
  const Json seed = {{"collidoscope_surface_distance", 1},
                     {"name", "blades"},
                     {"model_size", 3.4},
                     {"seed", Json::array({{{"bound", "hull"}}})},
                     {"backends", Json::array()}};
  const Json obbtree = {{"collidoscope_surface_distance", 1},
                        {"seed", Json::array()},
                        {"reference", {{"lower", 0.3}, {"upper", 0.3}}},
                        {"backends", Json::array({{{"backend", "obbtree"}, {"status", "ok"}}})}};
  CombinationResult crashed = part(InputKind::kSurfaces, "fcl:rss", Json());
  crashed.outcome.status = WorkerStatus::kCrashed;
  crashed.outcome.signal_name = "SIGSEGV";
  crashed.outcome.log_tail = "building\nfcl: bad\n";
  CombinationResult scene = part(InputKind::kScene, "obbtree", Json());

  const std::map<std::string, Json> documents =
      comparisonDocuments({part(InputKind::kSurfaces, "obbtree", obbtree), crashed, scene,
                           part(InputKind::kSurfaces, kSeedMethod, seed)});
  ASSERT_EQ(documents.size(), 1u);  // the mesh scene has none
  const Json& d = documents.at("surfaces/blades");
  EXPECT_EQ(d.at("model_size"), 3.4);      // the seed's figures
  EXPECT_EQ(d.at("seed").size(), 1u);      // and its rows
  EXPECT_TRUE(d.contains("reference"));    // from a backend's answer
  ASSERT_EQ(d.at("backends").size(), 2u);  // in backend order
  EXPECT_EQ(d.at("backends")[0].at("backend"), "fcl:rss");
  EXPECT_EQ(d.at("backends")[0].at("status"), "crashed (SIGSEGV): fcl: bad");
  EXPECT_EQ(d.at("backends")[0].at("segments"), 0);
  EXPECT_EQ(d.at("backends")[1].at("backend"), "obbtree");
  EXPECT_FALSE(d.contains("problems"));
}

TEST(ComparisonDocuments, ASeedThatDiedIsAProblemAndTheBackendsStillShow) {
  CombinationResult seed = part(InputKind::kFrep, kSeedMethod, Json());
  seed.outcome.status = WorkerStatus::kTimeout;
  const Json ode = {{"collidoscope_frep", 1},
                    {"name", "blades"},
                    {"precision", 0.001},
                    {"seed", Json::array()},
                    {"comparators", Json::array({{{"backend", "ode"}, {"status", "ok"}}})}};
  CombinationResult failed = part(InputKind::kFrep, "bullet", Json());
  failed.outcome.status = WorkerStatus::kFailed;
  failed.outcome.exit_code = 2;

  const std::map<std::string, Json> documents =
      comparisonDocuments({seed, part(InputKind::kFrep, "ode", ode), failed});
  const Json& d = documents.at("frep/blades");
  EXPECT_EQ(d.at("collidoscope_frep"), 1);
  EXPECT_EQ(d.at("precision"), 0.001);
  EXPECT_TRUE(d.at("seed").empty());
  EXPECT_EQ(d.at("problems"), Json::array({"seed method: timeout"}));
  ASSERT_EQ(d.at("comparators").size(), 2u);
  EXPECT_EQ(d.at("comparators")[0].at("status"), "failed (exit 2)");
  EXPECT_EQ(d.at("comparators")[0].at("resolution"), "8,32");
  EXPECT_EQ(d.at("comparators")[1].at("backend"), "ode");
}

}  // namespace
}  // namespace collido::study
