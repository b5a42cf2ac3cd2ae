// collido tracks: writes the marker tracks of a scene's tracked objects (generated or read) as
// one CSV file, so generated tracks, with their ground truth in the scene, can feed other tools
// or a scene of their own ("tracks": FILE).
#include <iostream>

#include <collido/scene/marker_tracks_file.h>
#include <collido/scene/scene.h>

#include "commands.h"

namespace collido::cli {
namespace {

int writeTracks(const std::string& scene_path, const std::string& output) {
  Result<Scene> scene = loadScene(scene_path);
  if (!scene.ok()) {
    std::cerr << "error: " << scene.status().message() << "\n";
    return 2;
  }
  std::vector<std::pair<std::string, MarkerTracks>> objects;
  std::size_t rows = 0;
  for (const SceneObject& object : scene.value().objects) {
    if (!object.tracking) continue;
    MarkerTracks tracks;
    for (const TrackedFrame& frame : object.tracking->frames) {
      tracks.push_back(frame.observed);
      rows += frame.observed.size();
    }
    objects.emplace_back(object.name, std::move(tracks));
  }
  if (objects.empty()) {
    std::cerr << "error: " << scene_path << ": no object has tracked markers (\"markers\")\n";
    return 2;
  }
  if (Status s = writeMarkerTracks(output, objects); !s.ok()) {
    std::cerr << "error: " << s.message() << "\n";
    return 2;
  }
  std::cerr << output << ": " << rows << " rows, " << objects.size() << " tracked object"
            << (objects.size() == 1 ? "" : "s") << ", " << scene.value().frames << " frames\n";
  return 0;
}

}  // namespace

void addTracksCommand(CLI::App& app, int& exit_code) {
  auto scene = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "tracks",
      "Write the marker tracks of a scene's tracked objects (generated or read) as one CSV file "
      "(frame,object,marker,x,y,z,weight; scenes/README.md)");
  command->add_option("scene", *scene, "scene file (JSON)")->required();
  command->add_option("-o,--output", *output, "the CSV file")->required();
  command->callback([scene, output, &exit_code] { exit_code = writeTracks(*scene, *output); });
}

}  // namespace collido::cli
