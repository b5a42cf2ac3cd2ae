// `collido study robot.urdf --trajectory joints.csv --environment ...`: a robot studied in one
// command, imported as `collido import urdf` does into the study folder's scenes/.
#include <cctype>
#include <filesystem>
#include <ostream>

#include <collido/urdf/urdf_import.h>

#include "commands.h"

namespace collido::cli {
namespace {

bool isUrdf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".urdf";
}

}  // namespace

void addRobotInputOptions(CLI::App& command, RobotInputOptions& options) {
  command.add_option("--trajectory", options.trajectory,
                     "with a URDF among the scenes: its joints CSV (as collido import urdf; "
                     "default: seeded random configurations)");
  command.add_option("--environment", options.environment,
                     "with a URDF among the scenes: mesh files fixed in the world, each FILE or "
                     "FILE@X,Y,Z[,ROLL,PITCH,YAW] (as collido import urdf)");
}

Status importRobotInputs(std::vector<std::string>& scenes, const RobotInputOptions& options,
                         const std::string& out, std::ostream& err) {
  UrdfImportRequest request;
  request.trajectory = options.trajectory;
  if (Status s = parseEnvironmentMeshes(options.environment, request.environment); !s.ok())
    return s;
  bool any = false;
  for (std::string& scene : scenes) {
    if (!isUrdf(scene)) continue;
    any = true;
    request.urdf = scene;
    request.output =
        (std::filesystem::path(out) / "scenes" / std::filesystem::path(scene).stem()).string() +
        ".json";
    const Result<UrdfImport> imported = importUrdf(request);
    if (!imported.ok()) return imported.status();
    err << "scene of the robot: " << request.output << " (" << imported.value().objects
        << " objects, " << imported.value().frames << " frames)\n";
    scene = request.output;
  }
  if (!any && (!options.trajectory.empty() || !options.environment.empty())) {
    return Status(StatusCode::kInvalidArgument,
                  std::string(options.trajectory.empty() ? "--environment" : "--trajectory") +
                      " is for a robot: give its URDF file among the scenes");
  }
  return {};
}

}  // namespace collido::cli
