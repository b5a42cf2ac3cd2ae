// Joining a surface or FRep file's combinations into the document its command would write.
#include <collido/study/comparison_files.h>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

using Json = nlohmann::json;

CombinationResult part(InputKind kind, const std::string& backend) {
  CombinationResult r;
  r.combination.kind = kind;
  r.combination.scene_path = "/data/scenes/surfaces/blades.json";
  r.combination.scene_name = "blades";
  r.combination.backend = backend;
  r.combination.grid = {8, 32};
  return r;
}

TEST(ComparisonDocuments, SeedRowsThenEveryBackendsRowsAndTheWorkersThatDied) {
  CombinationResult seed = part(InputKind::kSurfaces, kSeedMethod);
  seed.surfaces.emplace();
  seed.surfaces->file = seed.combination.scene_path;
  seed.surfaces->model_size = 3.4;
  seed.surfaces->seed.emplace_back();
  CombinationResult obbtree = part(InputKind::kSurfaces, "obbtree");
  obbtree.surfaces.emplace();
  obbtree.surfaces->reference.emplace();
  obbtree.surfaces->reference->lower = 0.3;
  obbtree.surfaces->reference->upper = 0.3;
  obbtree.surfaces->backends.emplace_back();
  obbtree.surfaces->backends.back().backend = "obbtree";
  obbtree.surfaces->backends.back().segments = 8;
  CombinationResult crashed = part(InputKind::kSurfaces, "fcl:rss");
  crashed.outcome.status = WorkerStatus::kCrashed;
  crashed.outcome.signal_name = "SIGSEGV";
  crashed.outcome.log_tail = "building\nfcl: bad\n";
  const CombinationResult scene = part(InputKind::kScene, "obbtree");

  const std::map<std::string, Json> documents =
      comparisonDocuments({obbtree, crashed, scene, seed});
  ASSERT_EQ(documents.size(), 1u);  // the mesh scene has none
  const Json& d = documents.at("surfaces/blades");
  EXPECT_EQ(d.at("name"), "blades");
  EXPECT_EQ(d.at("model_size"), 3.4);             // the seed's figures
  EXPECT_EQ(d.at("seed").size(), 1u);             // and its rows
  EXPECT_EQ(d.at("reference").at("lower"), 0.3);  // from a backend's answer
  ASSERT_EQ(d.at("backends").size(), 2u);         // in backend order
  EXPECT_EQ(d.at("backends")[0].at("backend"), "fcl:rss");
  EXPECT_EQ(d.at("backends")[0].at("status"), "crashed (SIGSEGV): fcl: bad");
  EXPECT_EQ(d.at("backends")[0].at("segments"), 0);
  EXPECT_EQ(d.at("backends")[1].at("backend"), "obbtree");
  EXPECT_EQ(d.at("backends")[1].at("status"), "ok");
  EXPECT_FALSE(d.contains("problems"));
}

TEST(ComparisonDocuments, ASeedThatDiedIsAProblemAndTheBackendsStillShow) {
  CombinationResult seed = part(InputKind::kFrep, kSeedMethod);
  seed.outcome.status = WorkerStatus::kTimeout;
  CombinationResult ode = part(InputKind::kFrep, "ode");
  ode.frep.emplace();
  ode.frep->name = "blades";
  ode.frep->precision = 0.001;
  ode.frep->comparators.emplace_back();
  ode.frep->comparators.back().backend = "ode";
  ode.frep->comparators.back().resolution = 8;
  CombinationResult failed = part(InputKind::kFrep, "bullet");
  failed.outcome.status = WorkerStatus::kFailed;
  failed.outcome.exit_code = 2;

  const std::map<std::string, Json> documents = comparisonDocuments({seed, ode, failed});
  const Json& d = documents.at("frep/blades");
  EXPECT_EQ(d.at("collidoscope_frep"), 1);
  EXPECT_EQ(d.at("precision"), 0.001);
  EXPECT_TRUE(d.at("seed").empty());
  EXPECT_EQ(d.at("problems"), Json::array({"seed method: timeout"}));
  ASSERT_EQ(d.at("comparators").size(), 3u);  // the failed worker's grid, then ode's row
  EXPECT_EQ(d.at("comparators")[0].at("status"), "failed (exit 2)");
  EXPECT_EQ(d.at("comparators")[0].at("resolution"), 8);
  EXPECT_EQ(d.at("comparators")[1].at("resolution"), 32);
  EXPECT_EQ(d.at("comparators")[2].at("backend"), "ode");
  EXPECT_EQ(d.at("comparators")[2].at("status"), "ok");
}

}  // namespace
}  // namespace collido::study
