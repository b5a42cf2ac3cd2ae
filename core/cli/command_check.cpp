#include <iostream>

#include <Eigen/Geometry>

#include <collido/scene/scene.h>
#include <collido/scene/tracking_summary.h>

#include "commands.h"

namespace collido::cli {
namespace {

void printPlacement(const Scene& scene) {
  const ScenePlacement& p = *scene.placement;
  std::cout << "  constraints: " << p.constraints << " solved at load (" << p.equations
            << " equations over " << p.parameters << " free parameters, " << p.iterations
            << " Newton iterations, normalised change " << p.change << ")";
  for (std::size_t k = 0; k < p.moved.size(); ++k) {
    const Pose& c = p.corrections[k];
    std::cout << (k == 0 ? "; moved " : ", ") << scene.objects[p.moved[k]].name << " by "
              << c.translation().norm() << " and "
              << Eigen::AngleAxisd(c.linear()).angle() * 180.0 / 3.14159265358979323846
              << " degrees";
  }
  std::cout << "\n";
  for (const auto& [name, value] : p.variables)
    std::cout << "    variable " << name << " = " << value << "\n";
  for (const auto& [name, distance] : p.clearances)
    std::cout << "    clearance " << name << ": exact distance " << distance << "\n";
}

int checkScenes(const std::vector<std::string>& paths) {
  int failures = 0;
  for (const std::string& path : paths) {
    Result<Scene> loaded = loadScene(path);
    if (!loaded.ok()) {
      std::cout << "error: " << loaded.status().message() << "\n";
      ++failures;
      continue;
    }
    const Scene& scene = loaded.value();
    std::cout << scene.name << " (" << path << "): " << scene.frames << " frame"
              << (scene.frames == 1 ? "" : "s") << ", " << scene.objects.size() << " objects, "
              << scene.queries.size() << " queries\n";
    if (!scene.description.empty()) std::cout << "  " << scene.description << "\n";
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const SceneObject& o = scene.objects[i];
      std::cout << "  object " << o.name << ": " << o.report.summary()
                << (o.parent ? ", on " + scene.objects[*o.parent].name : std::string())
                << (o.poses.size() == 1 ? ", fixed pose" : ", moving");
      if (!o.present.everyFrame()) std::cout << ", exists in " << o.present.text();
      if (o.states.size() > 1) std::cout << ", " << o.states.size() << " active states";
      if (o.deformation) {
        const std::size_t rules = o.deformation->rules.size();
        std::cout << ", movable nodes (" << rules << " rule" << (rules == 1 ? "" : "s")
                  << (o.deformation->recorded ? ", recorded positions" : "") << ")";
      }
      std::cout << "\n";
      if (o.tracking) {
        std::cout << "    poses from " << summarizeTracking(o).text(*o.tracking) << "\n";
      }
    }
    if (scene.placement) printPlacement(scene);
    for (const SceneQuery& q : scene.queries) {
      std::cout << "  query " << q.name << ": " << queryKindName(q.request.kind) << " ";
      if (q.isGroup()) {
        if (q.side_b.empty()) {
          std::cout << "among " << q.among.size() << " objects, after a shared broad phase";
        } else {
          std::cout << (q.among.size() - q.side_b.size()) << " objects against " << q.side_b.size()
                    << ", after a shared broad phase";
        }
      } else {
        std::cout << scene.objects[q.a].name << " vs " << scene.objects[q.b].name;
      }
      if (!q.except.empty()) std::cout << ", except " << q.except.size() << " object pairs";
      if (q.request.max_pairs != 0) std::cout << ", at most " << q.request.max_pairs << " pairs";
      if (!q.asked.everyFrame()) std::cout << ", asked in " << q.asked.text();
      std::cout << "\n";
    }
  }
  return failures == 0 ? 0 : 1;
}

}  // namespace

void addCheckCommand(CLI::App& app, int& exit_code) {
  CLI::App* command =
      app.add_subcommand("check", "Load and validate scene files, and summarise them");
  auto paths = std::make_shared<std::vector<std::string>>();
  command->add_option("scenes", *paths, "scene files (JSON)")->required();
  command->callback([paths, &exit_code] { exit_code = checkScenes(*paths); });
}

}  // namespace collido::cli
