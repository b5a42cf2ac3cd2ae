// `--environment FILE@X,Y,Z[,ROLL,PITCH,YAW]`: an environment mesh and where it sits.
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <collido/urdf/urdf_import.h>

namespace collido {
namespace {

// The comma-separated numbers of `text`, or nothing when one is not a number (the '@' then
// belongs to the file's name).
std::optional<std::vector<double>> numberList(std::string_view text) {
  std::vector<double> numbers;
  while (true) {
    const std::size_t comma = text.find(',');
    const std::string_view token = text.substr(0, comma);
    double value = 0;
    const auto [stop, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    // Out of range reads as not finite, named below rather than taken as part of a name.
    if (token.empty() || stop != token.data() + token.size() ||
        (error != std::errc() && error != std::errc::result_out_of_range))
      return std::nullopt;
    numbers.push_back(error == std::errc() ? value : HUGE_VAL);
    if (comma == std::string_view::npos) return numbers;
    text.remove_prefix(comma + 1);
  }
}

}  // namespace

Result<EnvironmentMesh> parseEnvironmentMesh(const std::string& argument) {
  EnvironmentMesh mesh;
  const std::size_t at = argument.rfind('@');
  const std::optional<std::vector<double>> numbers =
      at == std::string::npos ? std::nullopt
                              : numberList(std::string_view(argument).substr(at + 1));
  if (!numbers) {
    mesh.file = argument;
    return mesh;
  }
  const std::vector<double>& n = *numbers;
  const std::string where = "--environment '" + argument + "': ";
  if (n.size() != 3 && n.size() != 6) {
    return Status(StatusCode::kInvalidArgument,
                  where + "a pose is X,Y,Z or X,Y,Z,ROLL,PITCH,YAW (metres, radians), got " +
                      std::to_string(n.size()) + " numbers");
  }
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!std::isfinite(n[i])) {
      static const char* const kNames[] = {"X", "Y", "Z", "ROLL", "PITCH", "YAW"};
      return Status(StatusCode::kInvalidArgument,
                    where + std::string(kNames[i]) + " is not a finite number");
    }
  }
  if (at == 0) return Status(StatusCode::kInvalidArgument, where + "no mesh file before the '@'");
  mesh.file = argument.substr(0, at);
  mesh.pose.translation() = Eigen::Vector3d(n[0], n[1], n[2]);
  if (n.size() == 6) {
    // URDF's rpy: about the fixed x, then y, then z axis.
    mesh.pose.linear() = (Eigen::AngleAxisd(n[5], Eigen::Vector3d::UnitZ()) *
                          Eigen::AngleAxisd(n[4], Eigen::Vector3d::UnitY()) *
                          Eigen::AngleAxisd(n[3], Eigen::Vector3d::UnitX()))
                             .toRotationMatrix();
  }
  return mesh;
}

Status parseEnvironmentMeshes(const std::vector<std::string>& arguments,
                              std::vector<EnvironmentMesh>& meshes) {
  std::vector<EnvironmentMesh> parsed;
  for (const std::string& argument : arguments) {
    Result<EnvironmentMesh> mesh = parseEnvironmentMesh(argument);
    if (!mesh.ok()) return mesh.status();
    parsed.push_back(std::move(mesh).value());
  }
  meshes = std::move(parsed);
  return {};
}

}  // namespace collido
