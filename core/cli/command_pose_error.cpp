// collido pose-error: how tracking noise, marker count, layout and dropouts become pose error,
// per solver, on a scene object's mesh (core/pose/error_sweep.h, runner/pose_error_report.h).
#include <iostream>
#include <map>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/pose/error_sweep.h>
#include <collido/runner/pose_error_report.h>
#include <collido/scene/scene.h>

#include "commands.h"

namespace collido::cli {
namespace {

struct PoseErrorArguments {
  std::string scene;
  std::string object;
  std::vector<std::string> solvers{"rigid", "affine"};
  std::vector<std::string> layouts{"spread", "compact", "planar"};
  std::vector<int> markers{3, 4, 6, 12};
  std::vector<double> noises{0.001};
  std::vector<double> dropouts{0.0};
  double outliers = 0.0;
  double outlier_offset = 0.05;
  double reject_outliers = 0.0;
  int trials = 200;
  std::uint64_t seed = 1;
  std::string json_path;
};

int poseError(const PoseErrorArguments& args) {
  Result<Scene> scene = loadScene(args.scene);
  if (!scene.ok()) {
    std::cerr << "error: " << scene.status().message() << "\n";
    return 2;
  }
  const SceneObject* object = nullptr;
  for (const SceneObject& o : scene.value().objects) {
    if (o.name == args.object) object = &o;
  }
  if (object == nullptr) {
    std::cerr << "error: " << args.scene << ": no object named '" << args.object << "'\n";
    return 2;
  }
  pose::ErrorSweepOptions options;
  options.solvers.clear();
  for (const std::string& s : args.solvers) {
    if (s != "rigid" && s != "affine") {
      std::cerr << "error: --solvers: '" << s << "' is not rigid or affine\n";
      return 2;
    }
    options.solvers.push_back(s == "rigid" ? pose::PoseSolver::kRigid : pose::PoseSolver::kAffine);
  }
  const std::map<std::string, pose::LayoutKind> kinds = {{"spread", pose::LayoutKind::kSpread},
                                                         {"compact", pose::LayoutKind::kCompact},
                                                         {"planar", pose::LayoutKind::kPlanar},
                                                         {"given", pose::LayoutKind::kGiven}};
  options.layouts.clear();
  for (const std::string& l : args.layouts) {
    const auto found = kinds.find(l);
    if (found == kinds.end()) {
      std::cerr << "error: --layouts: '" << l << "' is not spread, compact, planar or given\n";
      return 2;
    }
    if (found->second == pose::LayoutKind::kGiven && !object->tracking) {
      std::cerr << "error: --layouts given: object '" << args.object
                << "' has no marker layout (scene key \"markers\")\n";
      return 2;
    }
    options.layouts.push_back(found->second);
  }
  if (object->tracking) options.given = object->tracking->layout;
  options.marker_counts = args.markers;
  options.noises = args.noises;
  options.dropouts = args.dropouts;
  options.outliers = args.outliers;
  options.outlier_offset = args.outlier_offset;
  options.reject_outliers = args.reject_outliers;
  options.trials = args.trials;
  options.seed = args.seed;
  const Result<std::vector<pose::ErrorSweepRow>> rows =
      pose::runErrorSweep(object->mesh->vertices, options);
  if (!rows.ok()) {
    std::cerr << "error: " << rows.status().message() << "\n";
    return 2;
  }
  std::cout << object->name << " (" << object->mesh->vertexCount() << " vertices), " << args.trials
            << " random true poses a row, seed " << args.seed << "\n"
            << errorSweepText(rows.value());
  if (!args.json_path.empty()) {
    nlohmann::json json = {{"collidoscope_pose_error", 1},
                           {"scene", scene.value().name},
                           {"object", object->name},
                           {"trials", args.trials},
                           {"seed", args.seed},
                           {"rows", errorSweepRowsJson(rows.value())}};
    if (Status s = io::writeFileAtomically(args.json_path, json.dump(1) + "\n"); !s.ok()) {
      std::cerr << "error: " << s.message() << "\n";
      return 2;
    }
  }
  return 0;
}

}  // namespace

void addPoseErrorCommand(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PoseErrorArguments>();
  CLI::App* command = app.add_subcommand(
      "pose-error",
      "Measure pose error from tracked markers on a scene object's mesh: per solver (rigid, "
      "affine), marker layout (spread, compact, planar, given: the object's own), marker count, "
      "noise and dropout rate, over seeded random true poses");
  command->add_option("scene", args->scene, "scene file (JSON)")->required();
  command->add_option("--object", args->object, "the object whose mesh and markers are used")
      ->required();
  command->add_option("--solvers", args->solvers, "rigid, affine")->delimiter(',');
  command->add_option("--layouts", args->layouts, "spread, compact, planar, given")->delimiter(',');
  command->add_option("--markers", args->markers, "marker counts")
      ->delimiter(',')
      ->check(CLI::Range(3, 10000));
  command->add_option("--noise", args->noises, "per-axis noise standard deviations")
      ->delimiter(',')
      ->check(nonNegativeNumber());
  command->add_option("--dropout", args->dropouts, "chances a marker is not seen")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 1.0));
  command->add_option("--outliers", args->outliers, "chance a seen marker is mis-identified")
      ->check(CLI::Range(0.0, 1.0));
  command->add_option("--outlier-offset", args->outlier_offset, "how far it lands")
      ->check(nonNegativeNumber());
  command
      ->add_option("--reject-outliers", args->reject_outliers,
                   "residual limit of the outlier rejection (0: off)")
      ->check(nonNegativeNumber());
  command->add_option("--trials", args->trials, "random true poses per row")
      ->check(CLI::Range(1, 1000000));
  command->add_option("--seed", args->seed, "seed of the poses and noise");
  command->add_option("--json", args->json_path, "also write the rows as JSON");
  command->callback([args, &exit_code] { exit_code = poseError(*args); });
}

}  // namespace collido::cli
