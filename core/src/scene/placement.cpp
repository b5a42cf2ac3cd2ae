#include <collido/scene/placement.h>

#include <nlohmann/json.hpp>

#include <collido/io/scene_pose.h>

#include "scene_reader.h"

namespace collido {
namespace {

using Json = nlohmann::json;

}  // namespace

Result<std::string> placedSceneText(const std::string& path, const SceneLoadOptions& options) {
  Result<Scene> loaded = loadScene(path, options);
  if (!loaded.ok()) return loaded.status();
  const Scene& scene = loaded.value();
  if (!scene.placement) {
    return Status(StatusCode::kInvalidArgument, path + ": the scene has no 'constraints' block");
  }
  Result<std::string> text = scene_reading::readTextFile(path, "scene file");
  if (!text.ok()) return text.status();
  Result<Json> parsed = scene_reading::parseDocument(text.value(), path);
  if (!parsed.ok()) return parsed.status();
  Json document = std::move(parsed.value());
  for (std::size_t index : scene.placement->moved) {
    const SceneObject& object = scene.objects[index];
    Json& node = document["objects"][index];
    if (node.contains("motion") && node["motion"].contains("poses")) {
      Json& keyframes = node["motion"]["poses"];
      for (std::size_t f = 0; f < keyframes.size(); ++f)
        keyframes[f] = io::scenePoseJson(object.poses[f]);
    } else if (node.contains("motion") && node["motion"].contains("linear")) {
      node["motion"]["linear"]["from"] = io::scenePoseJson(object.poses.front());
      node["motion"]["linear"]["to"] = io::scenePoseJson(object.poses.back());
    } else {
      node["pose"] = io::scenePoseJson(object.poses.front());
    }
  }
  Json& variables = document["constraints"]["variables"];
  for (std::size_t k = 0; k < scene.placement->variables.size(); ++k)
    variables[k]["value"] = scene.placement->variables[k].second;
  if (variables.empty()) document["constraints"].erase("variables");
  return document.dump(1) + "\n";
}

}  // namespace collido
