// The oracle's answers kept on disk between workers: they come back exactly, only for the
// identical scene, and a broken file is reported and adds nothing.
#include <collido/study/oracle_store.h>

#include <gtest/gtest.h>

#include <collido/scene/scene.h>

#include "support/test_paths.h"

namespace collido::study {
namespace {

// Two overlapping coplanar tori over three jittered frames: intersecting pairs in every frame.
constexpr const char* kScene = R"({
  "name": "stored", "frames": 3,
  "objects": [
    {"name": "a", "shape": {"generator": "torus", "major_segments": 16, "minor_segments": 8}},
    {"name": "b", "shape": {"generator": "torus", "major_segments": 16, "minor_segments": 8},
     "pose": {"translation": [0.3, 0.1, 0]},
     "motion": {"jitter": {"seed": 3, "translation": 0.05, "rotation_deg": 5}}}
  ],
  "queries": [{"a": "a", "b": "b", "kind": "all_pairs"}]
})";

Scene scene(const std::string& text = kScene) {
  Result<Scene> loaded = parseScene(text, "stored.json", ".");
  EXPECT_TRUE(loaded.ok()) << loaded.status().toString();
  return std::move(loaded).value();
}

TEST(OracleStore, AnswersComeBackExactly) {
  const Scene s = scene();
  OracleCache computed(s);
  for (std::size_t f = 0; f < s.frames; ++f)
    ASSERT_TRUE(computed.get(0, 1, f).intersecting);
  const std::string path = oracleStorePath(test::makeTempDirectory("oracle_store"), computed);
  ASSERT_TRUE(saveOracleAnswers(path, computed).ok());

  OracleCache loaded(s);
  ASSERT_TRUE(loadOracleAnswers(path, loaded).ok());
  ASSERT_EQ(loaded.answers().size(), computed.answers().size());
  for (const auto& [key, answer] : computed.answers()) {
    const OracleAnswer& back = loaded.answers().at(key);
    EXPECT_EQ(back.intersecting, answer.intersecting);
    EXPECT_EQ(back.pairs, answer.pairs);
    EXPECT_EQ(back.candidate_pairs, answer.candidate_pairs);
  }
}

// Distances come back bit for bit: the pair, the points and the distance.
TEST(OracleStore, DistancesComeBackExactly) {
  std::string text = kScene;
  text.replace(text.find("[0.3, 0.1, 0]"), 13, "[3.0, 0.0, 0]");
  text.replace(text.find("\"all_pairs\"}]"), 13, "\"distance\"}]");
  const Scene s = scene(text);
  OracleCache computed(s);
  int apart = 0;
  for (std::size_t f = 0; f < s.frames; ++f) {
    const OracleAnswer& answer = computed.get(0, 1, f, /*distance=*/true);
    ASSERT_TRUE(answer.distance.has_value());
    apart += answer.distance->distance > 0.0 ? 1 : 0;
  }
  EXPECT_EQ(apart, 3);
  const std::string path = oracleStorePath(test::makeTempDirectory("oracle_store"), computed);
  ASSERT_TRUE(saveOracleAnswers(path, computed).ok());
  OracleCache loaded(s);
  ASSERT_TRUE(loadOracleAnswers(path, loaded).ok());
  for (const auto& [key, answer] : computed.answers()) {
    const OracleAnswer& back = loaded.answers().at(key);
    ASSERT_TRUE(back.distance.has_value());
    EXPECT_EQ(back.distance->distance, answer.distance->distance);
    EXPECT_EQ(back.distance->pair, answer.distance->pair);
    EXPECT_EQ(back.distance->point_a, answer.distance->point_a);
    EXPECT_EQ(back.distance->point_b, answer.distance->point_b);
  }
}

// A run's link to the store: the second run reads what the first computed and computes nothing;
// without a folder nothing is read or written.
TEST(OracleStore, AStoredOracleReadsWhatAnEarlierRunKept) {
  const Scene s = scene();
  const std::string directory = test::makeTempDirectory("stored_oracle");
  {
    OracleCache first(s);
    const StoredOracle stored(directory, first);
    ASSERT_TRUE(first.get(0, 1, 0).intersecting);
    stored.keepNew();
  }
  OracleCache second(s);
  const StoredOracle stored(directory, second);
  EXPECT_EQ(second.answers().size(), 1u);
  EXPECT_TRUE(second.get(0, 1, 0).intersecting);
  EXPECT_EQ(second.computed(), 0u);

  OracleCache unstored(s);
  const StoredOracle none("", unstored);
  EXPECT_TRUE(unstored.answers().empty());
}

TEST(OracleStore, AMissingFileAddsNothingAndIsNoError) {
  const Scene s = scene();
  OracleCache cache(s);
  EXPECT_TRUE(
      loadOracleAnswers(test::makeTempDirectory("oracle_store") + "/none.json", cache).ok());
  EXPECT_TRUE(cache.answers().empty());
}

TEST(OracleStore, AnotherScenesAnswersAreRefused) {
  const Scene s = scene();
  OracleCache computed(s);
  (void)computed.get(0, 1, 0);
  const std::string path = test::makeTempDirectory("oracle_store") + "/answers.json";
  ASSERT_TRUE(saveOracleAnswers(path, computed).ok());

  std::string moved = kScene;
  moved.replace(moved.find("0.3, 0.1, 0"), 11, "0.2, 0.1, 0");
  const Scene other = scene(moved);
  OracleCache cache(other);
  EXPECT_NE(cache.fingerprint(), computed.fingerprint());
  const Status status = loadOracleAnswers(path, cache);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("another scene"), std::string::npos) << status.message();
  EXPECT_TRUE(cache.answers().empty());

  OracleCache witnesses(s, /*witness_only=*/true);
  EXPECT_NE(witnesses.fingerprint(), computed.fingerprint());
  EXPECT_FALSE(loadOracleAnswers(path, witnesses).ok());
}

TEST(OracleStore, ABrokenFileIsNamedAndAddsNothing) {
  const Scene s = scene();
  OracleCache cache(s);
  const std::string path = test::makeTempDirectory("oracle_store") + "/broken.json";
  const std::string head =
      R"({"fingerprint": ")" + cache.fingerprint() + R"(", "sizes": ")" + cache.inputSizes();
  test::writeFile(path,
                  head + R"(", "answers": [[0, 1, 0, true, 1, 1, [3, 4]], [0, 1, 1, true]]})");
  const Status status = loadOracleAnswers(path, cache);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find(path), std::string::npos) << status.message();
  EXPECT_TRUE(cache.answers().empty());

  test::writeFile(path, head + R"(", "answers": [[0, 1, 0, true, 1, 1, []]]})");
  EXPECT_FALSE(loadOracleAnswers(path, cache).ok()) << "a verdict without its pairs";
}

// Should two scenes ever share a digest, their sizes still tell them apart.
TEST(OracleStore, AnswersWhoseInputSizesDifferAreRefused) {
  const Scene s = scene();
  OracleCache cache(s);
  const std::string path = test::makeTempDirectory("oracle_store") + "/collision.json";
  test::writeFile(path, R"({"fingerprint": ")" + cache.fingerprint() +
                            R"(", "sizes": "frames 99, queries 1, objects 8v 12t 1p", )"
                            R"("answers": [[0, 1, 0, false, 0, 0, []]]})");
  const Status status = loadOracleAnswers(path, cache);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("its sizes, frames 99"), std::string::npos) << status.message();
  EXPECT_TRUE(cache.answers().empty());
}

TEST(OracleStore, TheFingerprintIsStableAcrossLoads) {
  EXPECT_EQ(OracleCache(scene()).fingerprint().size(), 32u);  // 128 bits
  EXPECT_EQ(OracleCache(scene()).fingerprint(), OracleCache(scene()).fingerprint());
}

}  // namespace
}  // namespace collido::study
