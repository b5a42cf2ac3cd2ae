// What each object is built for: its own queries' kinds, and the kinds linked to it through
// other objects' queries; and (with FCL) a backend that builds less for fewer kinds answers the
// same with less memory.
#include <collido/scene/scene.h>

#include <map>
#include <string>

#include <gtest/gtest.h>

#include <collido/runner/runner.h>

#include "support/runs/run_plugin.h"

namespace collido {
namespace {

// a-b distance and b-c boolean link a, b and c; all pairs among d, e and f link those; g-h is a
// distance only.
const char* const kLinkedScene = R"({"name": "linked", "frames": 3, "objects": [
  {"name": "a", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6}},
  {"name": "b", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "motion": {"linear": {"from": {"translation": [3, 0, 0]}, "to": {"translation": [1.5, 0, 0]}}}},
  {"name": "c", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "pose": {"translation": [3, 1.5, 0]}},
  {"name": "d", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "pose": {"translation": [0, 10, 0]}},
  {"name": "e", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "motion": {"linear": {"from": {"translation": [3, 10, 0]}, "to": {"translation": [1.5, 10, 0]}}}},
  {"name": "f", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "pose": {"translation": [0, 11.5, 0]}},
  {"name": "g", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "pose": {"translation": [0, 20, 0]}},
  {"name": "h", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6},
   "motion": {"linear": {"from": {"translation": [3, 20, 0]}, "to": {"translation": [1.5, 20, 0]}}}}],
 "queries": [{"name": "gap", "a": "a", "b": "b", "kind": "distance"},
             {"name": "touch", "a": "b", "b": "c", "kind": "boolean"},
             {"name": "pairs", "among": ["d", "e", "f"], "kind": "all_pairs"},
             {"name": "clear", "a": "g", "b": "h", "kind": "distance"}]})";

Scene linkedScene() {
  Result<Scene> scene = parseScene(kLinkedScene, "linked.json", ".");
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : Scene{};
}

TEST(SceneNeeds, LinkedKindsSpreadThroughSharedObjects) {
  const Scene scene = linkedScene();
  ASSERT_EQ(scene.objects.size(), 8u);
  const QueryKindSet gap_and_touch = QueryKindSet(QueryKind::kDistance) | QueryKind::kBoolean;
  EXPECT_EQ(scene.needsOf(0).queries, QueryKindSet(QueryKind::kDistance));
  EXPECT_EQ(scene.needsOf(1).queries, gap_and_touch);
  EXPECT_EQ(scene.needsOf(2).queries, QueryKindSet(QueryKind::kBoolean));
  // c is asked only booleans, but is linked through b to a distance query.
  for (std::size_t i : {0u, 1u, 2u})
    EXPECT_EQ(scene.needsOf(i).linked_queries, gap_and_touch) << i;
  for (std::size_t i : {3u, 4u, 5u}) {
    EXPECT_EQ(scene.needsOf(i).queries, QueryKindSet(QueryKind::kAllPairs)) << i;
    EXPECT_EQ(scene.needsOf(i).linked_queries, QueryKindSet(QueryKind::kAllPairs)) << i;
  }
  EXPECT_EQ(scene.needsOf(7).linked_queries, QueryKindSet(QueryKind::kDistance));
}

#ifdef COLLIDO_HAS_FCL
RunReport runObbRss(const Scene& scene, bool every) {
  RunOptions options = test::repeated(1);
  options.build_every_need = every;
  return test::runPlugin(scene, "fcl", "fcl:obbrss", options);
}

// FCL's OBBRSS keeps an OBB and an RSS per node; objects linked only to collision queries get
// FCL's OBB tree, only to distance its RSS tree. The two linked sets never mix box types, and
// every answer equals the one built for every kind.
TEST(SceneNeeds, FclBuildsOnlyTheBoxesTheLinkedKindsUse) {
  const Scene scene = linkedScene();
  const RunReport declared = runObbRss(scene, false);
  const RunReport every = runObbRss(scene, true);
  ASSERT_EQ(declared.measurements.size(), 4u);
  ASSERT_EQ(every.measurements.size(), 4u);
  for (std::size_t q = 0; q < 4; ++q) {
    const QueryMeasurement& d = declared.measurements[q];
    const QueryMeasurement& e = every.measurements[q];
    SCOPED_TRACE(d.query);
    ASSERT_TRUE(d.ok()) << d.status;
    ASSERT_TRUE(e.ok()) << e.status;
    EXPECT_EQ(d.disagreements, e.disagreements);
    ASSERT_EQ(d.frames.size(), e.frames.size());
    for (std::size_t f = 0; f < d.frames.size(); ++f) {
      EXPECT_EQ(d.frames[f].reported_intersecting, e.frames[f].reported_intersecting);
      EXPECT_EQ(d.frames[f].reported_pairs, e.frames[f].reported_pairs);
      ASSERT_EQ(d.frames[f].reported_distance.has_value(),
                e.frames[f].reported_distance.has_value());
      if (d.frames[f].reported_distance) {
        EXPECT_NEAR(*d.frames[f].reported_distance, *e.frames[f].reported_distance, 1e-12);
      }
    }
    // a, b and c are linked to both kinds: OBBRSS either way; d, e and f only to all pairs (OBB),
    // g and h only to distance (RSS).
    if (d.query == "pairs" || d.query == "clear") {
      EXPECT_LT(d.memory_bytes, e.memory_bytes);
    } else {
      EXPECT_EQ(d.memory_bytes, e.memory_bytes);
    }
  }
}
#endif

}  // namespace
}  // namespace collido
