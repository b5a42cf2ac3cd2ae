#include <fstream>
#include <iostream>

#include <collido/scene/placement.h>

#include "commands.h"

namespace collido::cli {
namespace {

int writePlacedScene(const std::string& path, const std::string& output) {
  const Result<std::string> text = placedSceneText(path);
  if (!text.ok()) {
    std::cerr << "error: " << text.status().message() << "\n";
    return 1;
  }
  std::ofstream out(output, std::ios::binary);
  out << text.value();
  if (!out.flush()) {
    std::cerr << "error: " << output << ": cannot write the placed scene\n";
    return 1;
  }
  std::cout << "wrote " << output << ": " << path << " with its constraints' solution\n";
  return 0;
}

}  // namespace

void addPlaceCommand(CLI::App& app, int& exit_code) {
  CLI::App* command = app.add_subcommand(
      "place", "Solve a scene's constraints and write the scene with the solved poses");
  auto scene = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  command->add_option("scene", *scene, "scene file (JSON) with a 'constraints' block")->required();
  command->add_option("-o,--output", *output, "where to write the placed scene (JSON)")->required();
  command->callback([scene, output, &exit_code] { exit_code = writePlacedScene(*scene, *output); });
}

}  // namespace collido::cli
