#include <collido/scene/placement.h>

#include <nlohmann/json.hpp>

#include "scene_reader.h"

namespace collido {
namespace {

using Json = nlohmann::json;

/// A pose as scenes/README.md writes it, with the rotation as a matrix: read back exactly.
Json poseJson(const Pose& pose) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i)
    rows.push_back({pose.linear()(i, 0), pose.linear()(i, 1), pose.linear()(i, 2)});
  const Eigen::Vector3d& t = pose.translation();
  return Json{{"translation", {t.x(), t.y(), t.z()}}, {"rotation", {{"matrix", rows}}}};
}

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
        keyframes[f] = poseJson(object.poses[f]);
    } else if (node.contains("motion") && node["motion"].contains("linear")) {
      node["motion"]["linear"]["from"] = poseJson(object.poses.front());
      node["motion"]["linear"]["to"] = poseJson(object.poses.back());
    } else {
      node["pose"] = poseJson(object.poses.front());
    }
  }
  Json& variables = document["constraints"]["variables"];
  for (std::size_t k = 0; k < scene.placement->variables.size(); ++k)
    variables[k]["value"] = scene.placement->variables[k].second;
  if (variables.empty()) document["constraints"].erase("variables");
  return document.dump(1) + "\n";
}

}  // namespace collido
