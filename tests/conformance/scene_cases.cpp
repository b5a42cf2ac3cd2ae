#include "scene_cases.h"

#include "conformance_target.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/study/oracle_store.h>

namespace collido::conformance {
namespace {

// Adversarial scenes of the kit itself, with exactly representable poses where contact must be
// exact: the oracle decides them exactly, so an exact backend must agree to the last pair.
constexpr const char* kKitScenes[] = {
    // Neighbouring links of a chain at pitch 2(R - r) touch exactly: with an even resolution both
    // tubes have vertices at the touching points; the quarter turn is an exact matrix.
    R"({"name": "kit_touching_links", "frames": 1,
        "objects": [
          {"name": "a", "shape": {"generator": "torus", "major_radius": 1, "minor_radius": 0.25,
                                  "major_segments": 32, "minor_segments": 16}},
          {"name": "b", "shape": {"generator": "torus", "major_radius": 1, "minor_radius": 0.25,
                                  "major_segments": 32, "minor_segments": 16},
           "pose": {"translation": [1.5, 0, 0],
                    "rotation": {"matrix": [[1, 0, 0], [0, 0, -1], [0, 1, 0]]}}}],
        "queries": [{"name": "all_pairs", "a": "a", "b": "b", "kind": "all_pairs"},
                    {"name": "boolean", "a": "a", "b": "b", "kind": "boolean"}]})",
    // Two flat sheets in one plane, the second shifted within it by exact fractions of a cell:
    // every overlapping pair is coplanar, and many edges and corners touch exactly.
    R"({"name": "kit_coplanar_sheets", "frames": 2,
        "objects": [
          {"name": "a", "shape": {"generator": "grid_sheet", "cells_x": 16, "cells_y": 16}},
          {"name": "b", "shape": {"generator": "grid_sheet", "cells_x": 16, "cells_y": 16},
           "motion": {"poses": [{"translation": [0.03125, 0.03125, 0]},
                                {"translation": [0.0625, 0, 0]}]}}],
        "queries": [{"name": "all_pairs", "a": "a", "b": "b", "kind": "all_pairs"},
                    {"name": "boolean", "a": "a", "b": "b", "kind": "boolean"}]})",
    R"({"name": "kit_random_tori", "frames": 12,
        "objects": [
          {"name": "a", "shape": {"generator": "torus", "major_segments": 40, "minor_segments": 20}},
          {"name": "b", "shape": {"generator": "torus", "major_segments": 40, "minor_segments": 20},
           "motion": {"random": {"seed": 77, "relative_to": "a", "overlap": [0.2, 0.95]}}}],
        "queries": [{"name": "all_pairs", "a": "a", "b": "b", "kind": "all_pairs"},
                    {"name": "boolean", "a": "a", "b": "b", "kind": "boolean"}]})",
    R"({"name": "kit_sphere_gear", "frames": 12,
        "objects": [
          {"name": "gear", "shape": {"generator": "gear", "teeth": 24, "module": 0.1}},
          {"name": "ball", "shape": {"generator": "sphere", "radius": 0.6, "slices": 24,
                                     "stacks": 12},
           "motion": {"random": {"seed": 78, "relative_to": "gear", "overlap": [0.1, 0.6]}}}],
        "queries": [{"name": "all_pairs", "a": "gear", "b": "ball", "kind": "all_pairs"},
                    {"name": "boolean", "a": "gear", "b": "ball", "kind": "boolean"}]})",
    // A torus thrown past and through another, turning: four of the six steps first touch
    // inside the step (near t = 0.09, 0.17, 0.52 and 0.54), two pass clear. Checks a plugin's
    // first contact over a step when it declares one, and its boolean at the frames.
    R"({"name": "kit_first_contact", "frames": 7,
        "objects": [
          {"name": "a", "shape": {"generator": "torus", "major_segments": 24, "minor_segments": 12}},
          {"name": "b", "shape": {"generator": "torus", "major_segments": 24, "minor_segments": 12},
           "motion": {"keyframes": [
             {"frame": 0, "pose": {"translation": [-3, 0.1, 0.2]}},
             {"frame": 1, "pose": {"translation": [3, 0.3, -0.1],
                                   "rotation": {"axis": [0, 1, 0], "degrees": 50}}},
             {"frame": 2, "pose": {"translation": [-3, 3.1, 0.4],
                                   "rotation": {"axis": [1, 0, 0], "degrees": 80}}},
             {"frame": 3, "pose": {"translation": [2.5, -0.2, 3],
                                   "rotation": {"axis": [1, 1, 0], "degrees": 120}}},
             {"frame": 4, "pose": {"translation": [0.3, 0.2, -2.5],
                                   "rotation": {"axis": [0, 0, 1], "degrees": 170}}},
             {"frame": 5, "pose": {"translation": [0.2, 0.1, 0.9],
                                   "rotation": {"axis": [0, 1, 1], "degrees": 30}}},
             {"frame": 6, "pose": {"translation": [3.5, 0.1, 0.9],
                                   "rotation": {"axis": [0, 1, 1], "degrees": 30}}}]}}],
        "queries": [{"name": "first_contact", "a": "a", "b": "b", "kind": "first_contact"},
                    {"name": "boolean", "a": "a", "b": "b", "kind": "boolean"}]})",
};

/// Where loadSceneCase finds placements and stored answers (loadSceneCases sets them).
struct Sources {
  std::string directory;
  std::string placement_store;
  std::string oracle_answers;
};

Sources& sources() {
  static Sources s;
  return s;
}

/// The scene's name as the loader gives it (its "name", else the stem of `label`, the file), or an
/// error naming `label`.
Result<std::string> sceneName(const nlohmann::json& json, const std::string& label) {
  if (!json.is_object()) {
    return Status(StatusCode::kInvalidArgument, label + ": not a scene (a JSON object)");
  }
  const auto name = json.find("name");
  if (name != json.end() && name->is_string() && !name->get<std::string>().empty())
    return name->get<std::string>();
  return std::filesystem::path(label).stem().string();
}

}  // namespace

std::vector<SceneCase>& sceneCases() {
  static std::vector<SceneCase> cases;
  return cases;
}

Status loadSceneCase(SceneCase& c) {
  if (c.loaded) return *c.loaded;
  SceneLoadOptions load;
  load.placement_store = sources().placement_store;
  Result<Scene> scene = c.path.empty()
                            ? parseScene(c.text, "conformance kit scene", sources().directory)
                            : loadScene(c.path, load);
  if (!scene.ok()) {
    c.loaded = scene.status();
    return *c.loaded;
  }
  if (scene.value().name != c.name) {  // the listing read the name another way than the loader
    c.loaded = Status(StatusCode::kInvalidArgument, c.path + ": the loader names the scene '" +
                                                        scene.value().name + "', the listing '" +
                                                        c.name + "'");
    return *c.loaded;
  }
  c.scene = std::make_shared<const Scene>(std::move(scene).value());
  c.oracle = std::make_shared<OracleCache>(*c.scene);
  std::error_code ec;
  if (!sources().oracle_answers.empty() &&
      std::filesystem::is_directory(sources().oracle_answers, ec)) {
    const std::string path = study::oracleStorePath(sources().oracle_answers, *c.oracle);
    if (Status s = study::loadOracleAnswers(path, *c.oracle); !s.ok())
      std::cerr << "collido_conformance: " << s.message() << "; computing the answers afresh\n";
  }
  c.loaded = Status();
  return *c.loaded;
}

Status storeOracleAnswers(const std::string& directory) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) return {StatusCode::kInvalidArgument, directory + ": " + ec.message()};
  for (const SceneCase& c : sceneCases()) {
    if (!c.oracle) continue;
    const std::string path = study::oracleStorePath(directory, *c.oracle);
    if (Status s = study::saveOracleAnswers(path, *c.oracle); !s.ok()) return s;
  }
  return {};
}

Status loadSceneCases(const std::string& directory, const std::set<std::string>& skipped,
                      const std::string& placement_store, const std::string& oracle_answers) {
  sources() = {directory, placement_store, oracle_answers};
  std::vector<std::string> files;
  std::set<std::string> not_found = skipped;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec)) {
    if (entry.path().extension() != ".json") continue;
    if (not_found.erase(entry.path().stem().string()) > 0) continue;
    files.push_back(entry.path().string());
  }
  if (ec) return {StatusCode::kInvalidArgument, directory + ": " + ec.message()};
  // A renamed scene must not silently leave the skip list meaning nothing.
  if (!not_found.empty()) {
    return {StatusCode::kInvalidArgument,
            directory + ": --skip-scenes names no scene file '" + *not_found.begin() + ".json'"};
  }
  std::sort(files.begin(), files.end());
  const auto add = [](const nlohmann::json& json, const std::string& label, const std::string& path,
                      const std::string& kit_text) -> Status {
    Result<std::string> name = sceneName(json, label);
    if (!name.ok()) return name.status();
    SceneCase c;
    c.name = name.value();
    c.test_name = gtestName(c.name);
    c.path = path;
    c.text = kit_text;
    sceneCases().push_back(std::move(c));
    return {};
  };
  for (const std::string& file : files) {
    Result<nlohmann::json> json = io::readJsonFile(file);
    if (!json.ok()) return json.status();
    if (Status s = add(json.value(), file, file, ""); !s.ok()) return s;
  }
  for (const char* text : kKitScenes) {
    const std::string label = "conformance kit scene";
    if (Status s = add(nlohmann::json::parse(text, nullptr, false), label, "", text); !s.ok())
      return s;
  }
  return {};
}

}  // namespace collido::conformance
