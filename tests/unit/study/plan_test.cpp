// Plans: nesting order, which scenes get other resolutions, ids, shards and the JSON form.
#include <collido/study/plan.h>

#include <cctype>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace collido::study {
namespace {

const std::vector<PlannedScene> kScenes = {
    {"/data/scenes/tori.json", "tori", true},
    {"/data/scenes/env_rob.json", "env_rob", false},
};

Sweep fullSweep() {
  Sweep sweep;
  sweep.resolutions = {1.0, 0.5};
  sweep.needs = {NeedsMode::kDeclared, NeedsMode::kEvery};
  sweep.limits = {0, 16};
  return sweep;
}

std::vector<std::string> idsOf(const std::vector<Combination>& plan) {
  std::vector<std::string> ids;
  for (const Combination& c : plan)
    ids.push_back(c.id);
  return ids;
}

// A scene with needs of its own runs those; the others the sweep's list.
TEST(PlanStudy, NeedsPerScene) {
  Sweep sweep;
  sweep.scene_needs["env_rob"] = {NeedsMode::kChanged, NeedsMode::kEvery};
  const std::vector<Combination> plan = planStudy(kScenes, {"obbtree"}, sweep);
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_EQ(plan[0].scene_name, "tori");
  EXPECT_EQ(plan[0].needs, NeedsMode::kDeclared);
  EXPECT_EQ(plan[1].needs, NeedsMode::kChanged);
  EXPECT_EQ(plan[1].settingText(), "needs=changed");
  EXPECT_EQ(plan[2].needs, NeedsMode::kEvery);
  EXPECT_NE(plan[1].id, plan[2].id);
}

TEST(PlanStudy, NestsScenesResolutionsBackendsNeedsLimits) {
  const std::vector<std::string> backends = {"obbtree", "fcl:obb[x=1]"};
  const std::vector<Combination> plan = planStudy(kScenes, backends, fullSweep());
  // tori: 2 resolutions x 2 backends x 2 needs x 2 limits; env_rob (mesh files): resolution 1 only.
  ASSERT_EQ(plan.size(), 16u + 8u);
  std::size_t i = 0;
  for (const PlannedScene& scene : kScenes) {
    for (const double resolution : {1.0, 0.5}) {
      if (resolution != 1.0 && !scene.has_generated_shapes) continue;
      for (const std::string& backend : backends) {
        for (const NeedsMode needs : {NeedsMode::kDeclared, NeedsMode::kEvery}) {
          for (const std::uint64_t limit : {0u, 16u}) {
            SCOPED_TRACE("combination " + std::to_string(i));
            const Combination& c = plan.at(i++);
            EXPECT_EQ(c.scene_path, scene.path);
            EXPECT_EQ(c.scene_name, scene.name);
            EXPECT_EQ(c.resolution, resolution);
            EXPECT_EQ(c.backend, backend);
            EXPECT_EQ(c.needs, needs);
            EXPECT_EQ(c.limit, limit);
          }
        }
      }
    }
  }
  EXPECT_EQ(i, plan.size());
}

TEST(PlanStudy, OtherResolutionsOnlyForGeneratedShapes) {
  Sweep sweep;
  sweep.resolutions = {0.5, 2.0};  // no 1 at all
  const std::vector<Combination> plan = planStudy(kScenes, {"obbtree"}, sweep);
  ASSERT_EQ(plan.size(), 2u);
  for (const Combination& c : plan)
    EXPECT_EQ(c.scene_name, "tori");
  EXPECT_EQ(plan[0].resolution, 0.5);
  EXPECT_EQ(plan[1].resolution, 2.0);
  EXPECT_TRUE(planStudy({kScenes[1]}, {"obbtree"}, sweep).empty());
}

TEST(PlanStudy, ASettingKeptToSomeScenesRunsOnlyThere) {
  Sweep sweep;
  const std::vector<Combination> plan =
      planStudy(kScenes, {"obbtree", "fcl:obb[rebuild=true]"}, sweep,
                {{"fcl:obb[rebuild=true]", {"tori", "not_studied"}}});
  std::vector<std::string> labels;
  for (const Combination& c : plan)
    labels.push_back(c.scene_name + " " + c.backend);
  EXPECT_EQ(labels, (std::vector<std::string>{"tori obbtree", "tori fcl:obb[rebuild=true]",
                                              "env_rob obbtree"}));
}

// A setting that answers none of a scene's kinds is not planned there, and is listed once per
// scene whatever the needs and limits; unknown abilities and unknown scene kinds plan as before.
TEST(PlanStudy, LeavesOutWhatDoesNotApplyAndListsItOnce) {
  const std::vector<PlannedScene> scenes = {
      {"/s/clearance.json", "clearance", false, "", QueryKind::kDistance},
      {"/s/contact.json", "contact", false, "",
       QueryKindSet(QueryKind::kBoolean) | QueryKind::kDistance},
      {"/s/old.json", "unknown_kinds", false, ""},
  };
  const SettingAbilities abilities = {
      {"bullet", {QueryKindSet(7), true}},
      {"nurbs:hull", {QueryKind::kDistance, false}},
      {"obbtree", {QueryKindSet(15), true}},
  };
  const std::vector<std::string> backends = {"obbtree", "bullet", "nurbs:hull", "unprobed"};
  const std::vector<Combination> plan = planStudy(scenes, backends, fullSweep(), {}, abilities);
  std::set<std::string> planned;
  for (const Combination& c : plan)
    planned.insert(c.scene_name + " " + c.backend);
  EXPECT_EQ(planned, (std::set<std::string>{"clearance obbtree", "clearance unprobed",
                                            "contact obbtree", "contact bullet", "contact unprobed",
                                            "unknown_kinds obbtree", "unknown_kinds bullet",
                                            "unknown_kinds nurbs:hull", "unknown_kinds unprobed"}));
  // 9 pairs x 2 needs x 2 limits; no scene has generated shapes.
  EXPECT_EQ(plan.size(), 9u * 4u);

  const std::vector<NotApplicable> left_out = notApplicable(scenes, backends, {}, abilities);
  ASSERT_EQ(left_out.size(), 3u);
  EXPECT_EQ(left_out[0].backend, "bullet");
  EXPECT_EQ(left_out[0].scene, "clearance");
  EXPECT_EQ(left_out[0].reason(), "answers boolean, all_pairs, contacts; the scene asks distance");
  EXPECT_EQ(left_out[1].backend, "nurbs:hull");
  EXPECT_EQ(left_out[1].reason(), "answers no triangle meshes; the scene asks distance");
  EXPECT_EQ(left_out[2].scene, "contact");
  EXPECT_EQ(left_out[2].backend, "nurbs:hull");

  // A pair the sweep keeps off a scene is not "not applicable" there.
  EXPECT_EQ(notApplicable(scenes, backends, {{"bullet", {"contact"}}}, abilities).size(), 2u);

  const std::string text = notApplicableText(left_out);
  EXPECT_NE(text.find("bullet      boolean, all_pairs, contacts  clearance (distance)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("clearance (distance), contact (boolean, distance)"), std::string::npos)
      << text;
  EXPECT_EQ(notApplicableText({}), "");
}

TEST(NotApplicableJson, RoundTripsAndNamesWhatIsWrong) {
  const std::vector<NotApplicable> list = {
      {"bullet", "clearance", QueryKind::kDistance, {QueryKindSet(7), true}},
      {"nurbs:hull", "pile", QueryKind::kBoolean, {QueryKind::kDistance, false}}};
  Result<std::vector<NotApplicable>> back =
      notApplicableFromJson(notApplicableToJson(list), "plan.json");
  ASSERT_TRUE(back.ok()) << back.status().message();
  ASSERT_EQ(back.value().size(), 2u);
  for (std::size_t i = 0; i < list.size(); ++i) {
    EXPECT_EQ(back.value()[i].backend, list[i].backend);
    EXPECT_EQ(back.value()[i].scene, list[i].scene);
    EXPECT_EQ(back.value()[i].asks, list[i].asks);
    EXPECT_EQ(back.value()[i].ability.queries, list[i].ability.queries);
    EXPECT_EQ(back.value()[i].ability.builds_meshes, list[i].ability.builds_meshes);
  }
  nlohmann::json bad = notApplicableToJson(list);
  bad[1]["asks"] = {"sometimes"};
  EXPECT_EQ(notApplicableFromJson(bad, "plan.json").status().message(),
            "plan.json: /not_applicable/1/asks: unknown query kind 'sometimes'");
  bad[1].erase("asks");
  EXPECT_NE(notApplicableFromJson(bad, "plan.json").status().message().find("plan.json"),
            std::string::npos);
}

TEST(PlanStudy, NoBackendsOrScenesPlanNothing) {
  EXPECT_TRUE(planStudy(kScenes, {}, fullSweep()).empty());
  EXPECT_TRUE(planStudy({}, {"obbtree"}, fullSweep()).empty());
}

TEST(PlanStudy, IdsAreUniqueStableAndFileNameSafe) {
  // Scene names and backend texts full of characters a file name must not hold.
  const std::vector<PlannedScene> scenes = {
      {"/a/b c.json", "b c/../x", true},
      {"/a/other.json", "b c/../x", true},  // same name, another file
      {"/a/long.json", std::string(200, 'n'), true},
  };
  const std::vector<std::string> backends = {"obbtree", "obbtree[a=1;b=x/y]", "obbtree[a=1;b=x:y]",
                                             "fcl:obb", "fcl_obb"};
  Sweep sweep = fullSweep();
  sweep.resolutions = {1.0, 0.5, 0.25};
  const std::vector<Combination> plan = planStudy(scenes, backends, sweep);
  ASSERT_EQ(plan.size(), 3u * 3u * 5u * 2u * 2u);
  const std::vector<std::string> ids = idsOf(plan);
  EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), ids.size());
  for (const std::string& id : ids) {
    SCOPED_TRACE(id);
    EXPECT_FALSE(id.empty());
    EXPECT_LE(id.size(), 100u);
    EXPECT_NE(id.front(), '.');
    for (const char c : id) {
      EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' ||
                  c == '.' || c == '~')
          << "character '" << c << "'";
    }
  }
  // The same inputs give the same ids (a resumed study finds its results again).
  EXPECT_EQ(idsOf(planStudy(scenes, backends, sweep)), ids);
}

TEST(PlanStudy, IdsTellApartResolutionsThatPrintAlike) {
  Sweep sweep;
  sweep.resolutions = {0.5, 0.50000001};
  const std::vector<Combination> plan = planStudy({kScenes[0]}, {"obbtree"}, sweep);
  ASSERT_EQ(plan.size(), 2u);
  EXPECT_NE(plan[0].id, plan[1].id);
}

// The inputs a combination's answers depend on are part of its id: a changed mesh, plugin
// version or repetition count gives another id, so results never mix across them.
TEST(PlanStudy, IdsFollowTheInputs) {
  const Combination c = planStudy({kScenes[0]}, {"obbtree"}, Sweep{}).front();
  const Combination with = withInputs(c, "digest1", "obbtree 0.4", 5);
  EXPECT_NE(with.id, c.id);
  EXPECT_EQ(withInputs(c, "digest1", "obbtree 0.4", 5).id, with.id);
  EXPECT_NE(withInputs(c, "digest2", "obbtree 0.4", 5).id, with.id);
  EXPECT_NE(withInputs(c, "digest1", "obbtree 0.5", 5).id, with.id);
  EXPECT_NE(withInputs(c, "digest1", "obbtree 0.4", 3).id, with.id);
  EXPECT_EQ(with.label(), c.label());  // people see the same combination
  const Result<Combination> back = combinationFromJson(combinationToJson(with));
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().scene_digest, "digest1");
  EXPECT_EQ(back.value().plugin_identity, "obbtree 0.4");
  EXPECT_EQ(back.value().repetitions, 5);
  EXPECT_EQ(back.value().id, with.id);
}

TEST(Combination, LabelAndSettingTextShowOnlyWhatDiffers) {
  Combination c;
  c.scene_name = "bunny_vs_bunny";
  c.backend = "obbtree[max_leaf_triangles=4]";
  EXPECT_EQ(c.settingText(), "");
  EXPECT_EQ(c.label(), "bunny_vs_bunny · obbtree[max_leaf_triangles=4]");
  c.needs = NeedsMode::kEvery;
  c.resolution = 0.5;
  c.limit = 16;
  EXPECT_EQ(c.settingText(), "needs=every r=0.5 limit=16");
  EXPECT_EQ(c.label(),
            "bunny_vs_bunny · obbtree[max_leaf_triangles=4] · needs=every r=0.5 limit=16");
}

TEST(ShardOf, ShardsPartitionThePlanExactly) {
  Sweep sweep = fullSweep();
  const std::vector<Combination> plan = planStudy(kScenes, {"obbtree", "fcl:obb", "bullet"}, sweep);
  ASSERT_EQ(plan.size(), 36u);
  for (std::size_t count : {1u, 2u, 3u, 5u, 7u, 36u, 50u}) {
    SCOPED_TRACE("count " + std::to_string(count));
    std::multiset<std::string> seen;
    std::size_t smallest = plan.size();
    std::size_t largest = 0;
    for (std::size_t index = 0; index < count; ++index) {
      const std::vector<Combination> part = shardOf(plan, index, count);
      smallest = std::min(smallest, part.size());
      largest = std::max(largest, part.size());
      // Each shard keeps plan order: every count-th combination from its index.
      for (std::size_t k = 0; k < part.size(); ++k)
        EXPECT_EQ(part[k].id, plan[index + k * count].id);
      for (const Combination& c : part)
        seen.insert(c.id);
    }
    const std::vector<std::string> ids = idsOf(plan);
    EXPECT_EQ(seen, std::multiset<std::string>(ids.begin(), ids.end()));  // union, disjoint
    EXPECT_LE(largest - smallest, 1u);                                    // fair sizes
  }
  EXPECT_EQ(idsOf(shardOf(plan, 0, 1)), idsOf(plan));
  EXPECT_TRUE(shardOf(plan, 0, 0).empty());
  EXPECT_TRUE(shardOf({}, 0, 4).empty());
}

TEST(ParseShard, AcceptsIndexOfCount) {
  for (const auto& [text, index, count] :
       std::vector<std::tuple<std::string, std::size_t, std::size_t>>{
           {"0/4", 0, 4}, {"3/4", 3, 4}, {"0/1", 0, 1}, {"12/100", 12, 100}}) {
    const Result<std::pair<std::size_t, std::size_t>> shard = parseShard(text);
    ASSERT_TRUE(shard.ok()) << text << ": " << shard.status().message();
    EXPECT_EQ(shard.value(), std::make_pair(index, count)) << text;
  }
}

TEST(ParseShard, RefusesEverythingElse) {
  for (const std::string text : {"4/4", "5/4", "0/0", "a/b", "1", "-1/2", "1/-2", "/4", "1/", "",
                                 "1/2/3", " 1/2", "1/2 ", "+1/2", "1.0/2", "9999999999/2"}) {
    const Result<std::pair<std::size_t, std::size_t>> shard = parseShard(text);
    ASSERT_FALSE(shard.ok()) << "'" << text << "' accepted";
    EXPECT_EQ(shard.status().code(), StatusCode::kInvalidArgument);
    EXPECT_NE(shard.status().message().find("'" + text + "'"), std::string::npos)
        << shard.status().message();
  }
}

TEST(CombinationJson, RoundTrips) {
  const std::vector<Combination> plan = planStudy(kScenes, {"obbtree[a=1]"}, fullSweep());
  ASSERT_FALSE(plan.empty());
  for (const Combination& c : plan) {
    const Result<Combination> back = combinationFromJson(combinationToJson(c));
    ASSERT_TRUE(back.ok()) << back.status().message();
    EXPECT_EQ(back.value().id, c.id);
    EXPECT_EQ(back.value().scene_path, c.scene_path);
    EXPECT_EQ(back.value().scene_name, c.scene_name);
    EXPECT_EQ(back.value().resolution, c.resolution);
    EXPECT_EQ(back.value().backend, c.backend);
    EXPECT_EQ(back.value().needs, c.needs);
    EXPECT_EQ(back.value().limit, c.limit);
    // And through text, as the worker's request file carries it.
    const Result<Combination> reparsed =
        combinationFromJson(nlohmann::json::parse(combinationToJson(c).dump()));
    ASSERT_TRUE(reparsed.ok());
    EXPECT_EQ(reparsed.value().id, c.id);
    EXPECT_EQ(reparsed.value().resolution, c.resolution);
  }
}

TEST(CombinationJson, RefusesMissingOrMistypedFields) {
  const nlohmann::json good = combinationToJson(planStudy(kScenes, {"obbtree"}, Sweep{}).front());
  for (const char* key : {"id", "scene_path", "scene", "resolution", "backend", "needs", "limit"}) {
    nlohmann::json missing = good;
    missing.erase(key);
    const Result<Combination> c = combinationFromJson(missing);
    ASSERT_FALSE(c.ok()) << "accepted without " << key;
    EXPECT_EQ(c.status().message().rfind("combination: ", 0), 0u) << c.status().message();
  }
  nlohmann::json bad_needs = good;
  bad_needs["needs"] = "all";
  EXPECT_FALSE(combinationFromJson(bad_needs).ok());
  nlohmann::json bad_limit = good;
  bad_limit["limit"] = "16";
  EXPECT_FALSE(combinationFromJson(bad_limit).ok());
  EXPECT_FALSE(combinationFromJson(nlohmann::json::array()).ok());
}

}  // namespace
}  // namespace collido::study
