// The viewer's data: a backend's kept answers (the pairs it reported and the oracle's, per frame
// and object pair) match the run's counts, and the page carries the scene's meshes and poses
// exactly as the scene holds them (the binary part decoded back), or names a missing front-end
// file.
#include <collido/view/view_page.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <collido/runner/runner.h>
#include <collido/runner/view_answers.h>
#include <collido/study/report_html.h>

#include "support/runs/run_plugin.h"
#include "support/test_paths.h"

namespace collido {
namespace {

using Json = nlohmann::json;

// Two spheres passing through each other, and a box on the second (a child).
const char* const kScene = R"({"name": "passing", "frames": 4, "objects": [
  {"name": "fixed", "shape": {"generator": "sphere", "radius": 1, "slices": 12, "stacks": 6}},
  {"name": "moving", "shape": {"generator": "sphere", "radius": 0.6, "slices": 10, "stacks": 5},
   "motion": {"linear": {"from": {"translation": [-3, 0.2, 0]}, "to": {"translation": [0.8, 0.2, 0]}}}},
  {"name": "tag", "parent": "moving", "shape": {"generator": "box", "size": [0.2, 0.2, 0.2]},
   "pose": {"translation": [0, 0.7, 0]}}],
  "queries": [{"name": "pairs", "a": "fixed", "b": {"subtree": "moving"}, "kind": "all_pairs"},
              {"name": "gap", "a": "fixed", "b": "moving", "kind": "distance"},
              {"name": "touch", "a": "fixed", "b": "moving", "kind": "boolean"}]})";

Scene loadTestScene() {
  Result<Scene> scene = parseScene(kScene, "passing.json", ".");
  EXPECT_TRUE(scene.ok()) << scene.status().toString();
  return std::move(scene).value();
}

RunReport runObbTree(const Scene& scene) {
  RunOptions options = test::repeated(1);
  options.keep_answers = true;
  return test::runPlugin(scene, "obbtree", "obbtree", options);
}

TEST(ViewAnswers, KeptPairsAreTheRunsCounts) {
  const Scene scene = loadTestScene();
  const RunReport report = runObbTree(scene);
  const Json answers = Json::parse(viewAnswersJson(scene, report, "obbtree"));
  EXPECT_EQ(answers["backend"], "obbtree");
  ASSERT_EQ(answers["queries"].size(), report.measurements.size());
  std::size_t pairs = 0;
  std::size_t witnesses = 0;
  for (std::size_t q = 0; q < report.measurements.size(); ++q) {
    const QueryMeasurement& m = report.measurements[q];
    const Json& query = answers["queries"][q];
    EXPECT_EQ(query["name"], m.query);
    ASSERT_EQ(query["frames"].size(), m.frames.size());
    for (std::size_t f = 0; f < m.frames.size(); ++f) {
      const Json& frame = query["frames"][f];
      std::size_t reported = 0;
      std::size_t exact = 0;
      for (const Json& pair : frame["pairs"]) {
        reported += pair["reported"].size() / 2;
        exact += pair["oracle"].size() / 2;
        if (m.kind == QueryKind::kDistance) {
          ASSERT_TRUE(pair["oracle_distance"].is_object());
          EXPECT_NEAR(pair["distance"]["value"].get<double>(),
                      pair["oracle_distance"]["value"].get<double>(), 1e-9);
        }
      }
      EXPECT_EQ(frame["pairs"].size(), m.frames[f].object_pairs);
      EXPECT_EQ(frame["disagrees"], m.frames[f].disagrees(m.kind)) << "frame " << f;
      if (m.kind == QueryKind::kBoolean) {
        // The OBB tree's witnesses are real, and the page can tell without the full oracle set.
        for (const Json& pair : frame["pairs"]) {
          ASSERT_EQ(pair["reported_exact"].size(), pair["reported"].size() / 2);
          for (const Json& real : pair["reported_exact"])
            EXPECT_TRUE(real.get<bool>()) << "frame " << f;
          witnesses += pair["reported_exact"].size();
        }
      }
      if (m.kind == QueryKind::kAllPairs) {
        EXPECT_EQ(reported, m.frames[f].reported_pairs) << "frame " << f;
        EXPECT_EQ(exact, m.frames[f].oracle_pairs) << "frame " << f;
        pairs += exact;
      }
    }
  }
  EXPECT_GT(pairs, 0u) << "the spheres should meet";
  EXPECT_GT(witnesses, 0u) << "the boolean query should name witness pairs";
}

// A front-end folder with a template naming every part, and stand-ins for the scripts; one per
// test and process, since CTest runs tests (and the Release and sanitizer builds) side by side.
std::string fakeWebDirectory() {
  const std::filesystem::path web =
      std::filesystem::temp_directory_path() /
      ("collido_view_web_" +
       std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
       std::to_string(::getpid()));
  std::filesystem::remove_all(web);
  std::filesystem::create_directories(web / "view");
  std::filesystem::create_directories(web / "node_modules/three/build");
  std::filesystem::create_directories(web / "node_modules/three/examples/jsm/controls");
  const auto write = [](const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
  };
  write(web / "view/template.html",
        "<title>@TITLE@</title><style>@CSS@</style><data>@DATA@</data><geometry>@GEOMETRY@"
        "</geometry>@THREE_CORE@|@THREE_MODULE@|@ORBIT_CONTROLS@|@VIEW_JS@");
  write(web / "view/view.css", "css");
  write(web / "view/view.js", "view('</script>')");
  write(web / "node_modules/three/build/three.core.js", "core");
  write(web / "node_modules/three/build/three.module.js", "module");
  write(web / "node_modules/three/examples/jsm/controls/OrbitControls.js", "controls");
  return web.string();
}

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t start = text.find(open);
  const std::size_t stop = text.find(close, start);
  EXPECT_NE(start, std::string::npos);
  return text.substr(start + open.size(), stop - start - open.size());
}

std::string unbase64(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  int bits = 0;
  unsigned value = 0;
  for (const char c : text) {
    const std::size_t digit = alphabet.find(c);
    if (digit == std::string::npos) continue;  // '=' padding
    value = (value << 6) | static_cast<unsigned>(digit);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((value >> bits) & 0xff);
    }
  }
  return out;
}

TEST(ViewPage, CarriesTheScenesMeshesPosesAndAnswers) {
  const Scene scene = loadTestScene();
  const RunReport report = runObbTree(scene);
  const std::vector<view::ViewBackend> backends = {
      {"obbtree", viewAnswersJson(scene, report, "obbtree"), ""},
      {"crashy", "", "crashed (SIGSEGV): boom"},
      {"garbled", "", "crashed: its log ends in \xe2\x82"}};
  const Result<std::string> page = view::renderViewPage(scene, backends, fakeWebDirectory());
  ASSERT_TRUE(page.ok()) << page.status().toString();
  const std::string& html = page.value();
  EXPECT_NE(html.find("<title>passing</title>"), std::string::npos);
  EXPECT_NE(html.find("view('<\\/script>')"), std::string::npos) << "scripts are made safe";

  const Json data = Json::parse(between(html, "<data>", "</data>"));
  const std::string geometry = unbase64(between(html, "<geometry>", "</geometry>"));
  ASSERT_EQ(data["objects"].size(), 3u);
  EXPECT_EQ(data["objects"][2]["parent"], 1);
  EXPECT_EQ(data["scene"]["frames"], 4);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& object = scene.objects[i];
    const Json& entry = data["objects"][i];
    const TriangleMesh& mesh = *object.mesh;
    const auto [vertex_offset, vertex_count] =
        entry["states"][0]["positions"].get<std::pair<std::size_t, std::size_t>>();
    const auto [index_offset, index_count] =
        entry["states"][0]["indices"].get<std::pair<std::size_t, std::size_t>>();
    ASSERT_EQ(vertex_count, static_cast<std::size_t>(mesh.vertices.size()));
    ASSERT_EQ(index_count, static_cast<std::size_t>(mesh.triangles.size()));
    ASSERT_LE(index_offset + 4 * index_count, geometry.size());
    for (std::size_t k = 0; k < vertex_count; ++k) {
      float value = 0;
      std::memcpy(&value, geometry.data() + vertex_offset + 4 * k, 4);
      ASSERT_EQ(value, static_cast<float>(mesh.vertices.data()[k])) << object.name << " " << k;
    }
    for (std::size_t k = 0; k < index_count; ++k) {
      std::uint32_t value = 0;
      std::memcpy(&value, geometry.data() + index_offset + 4 * k, 4);
      ASSERT_EQ(value, static_cast<std::uint32_t>(mesh.triangles.data()[k]));
    }
    // World poses, column by column, every frame (composed through the parent).
    for (std::size_t f = 0; f < scene.frames; ++f) {
      const Json& pose = entry["poses"].size() == 1 ? entry["poses"][0] : entry["poses"][f];
      for (int k = 0; k < 16; ++k)
        ASSERT_EQ(pose[k].get<double>(), object.poseAt(f).matrix().data()[k]);
    }
  }
  ASSERT_EQ(data["backends"].size(), 3u);
  EXPECT_EQ(data["backends"][2]["problem"], "crashed: its log ends in \xef\xbf\xbd")
      << "bytes that are not UTF-8 are replaced, not allowed to lose the page";
  EXPECT_EQ(data["backends"][0]["answers"]["backend"], "obbtree");
  EXPECT_EQ(data["backends"][1]["problem"], "crashed (SIGSEGV): boom");
  EXPECT_FALSE(data["backends"][1].contains("answers"));
  EXPECT_EQ(data["queries"][0]["side_b"], Json::array({1, 2}));
}

// A page may be shared: meshes are named as the scene names them, not by this machine's paths.
TEST(ViewPage, MeshesAreNamedRelativeToTheScene) {
  const Result<Scene> scene = loadScene(test::sourcePath("scenes/bunny_vs_bunny.json"));
  ASSERT_TRUE(scene.ok()) << scene.status().toString();
  const Result<std::string> page = view::renderViewPage(scene.value(), {}, fakeWebDirectory());
  ASSERT_TRUE(page.ok()) << page.status().toString();
  const Json data = Json::parse(between(page.value(), "<data>", "</data>"));
  EXPECT_EQ(data["objects"][0]["source"], "meshes/bunny.obj");
}

TEST(ViewPage, AMissingLibraryIsNamedWithHowToGetIt) {
  const std::string web = fakeWebDirectory();
  std::filesystem::remove(std::filesystem::path(web) / "node_modules/three/build/three.core.js");
  const Status checked = view::checkViewFrontEnd(web);
  ASSERT_FALSE(checked.ok());
  EXPECT_NE(checked.message().find("three.core.js: not found"), std::string::npos);
  const Result<std::string> page = view::renderViewPage(loadTestScene(), {}, web);
  ASSERT_FALSE(page.ok());
  EXPECT_NE(page.status().message().find("three.core.js: not found"), std::string::npos);
  EXPECT_NE(page.status().message().find("npm ci"), std::string::npos);
}

}  // namespace
}  // namespace collido
