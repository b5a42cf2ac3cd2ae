// `collido import urdf`: a robot described in URDF (read by urdfdom) becomes a scene: its links'
// collision geometry as objects mounted on their parents, its joints driving the frames, and the
// questions a robot's planner asks (self-collision, robot against environment, clearance).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <collido/status.h>

namespace collido {

/// A mesh fixed in the world: its file, and where it sits (identity: at its file's coordinates).
struct EnvironmentMesh {
  std::string file;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

/// Reads an environment argument: FILE, FILE@X,Y,Z or FILE@X,Y,Z,ROLL,PITCH,YAW (metres and
/// radians; roll, pitch and yaw about the fixed x, y and z axes, as URDF's `rpy`). Text after the
/// last '@' that is not such a list is part of the file's name. Fails naming the argument for a
/// list of another length or a number that is not finite.
Result<EnvironmentMesh> parseEnvironmentMesh(const std::string& argument);

/// Every argument read into `meshes` (replacing what it held), or the first one's failure.
Status parseEnvironmentMeshes(const std::vector<std::string>& arguments,
                              std::vector<EnvironmentMesh>& meshes);

/// What an import is asked.
struct UrdfImportRequest {
  std::string urdf;        ///< the robot
  std::string trajectory;  ///< joints CSV (a header of joint names, a row per frame); "": random
  std::vector<EnvironmentMesh> environment;  ///< meshes fixed in the world
  std::string output;                        ///< the scene file written
  std::size_t frames = 24;  ///< without a trajectory: seeded random configurations in the limits
  std::uint64_t seed = 1;
  /// Link pairs never asked, and link pairs asked whatever the rules say (names as in the URDF).
  std::vector<std::pair<std::string, std::string>> disable_pairs;
  std::vector<std::pair<std::string, std::string>> enable_pairs;
  /// Links whose clearance to each environment object is asked; empty: the link with the most
  /// joints above it.
  std::vector<std::string> clearance_links;
  /// Links whose first contact with each environment object is asked over every step (the
  /// links' poses interpolated between frames, StepMotion); empty: none.
  std::vector<std::string> first_contact_links;
  /// Ask the first-contact queries alone (a planner's edge checks), not self-collision, the
  /// environment and clearance at the frames.
  bool first_contact_only = false;
};

/// What an import wrote.
struct UrdfImport {
  std::string robot;
  std::size_t objects = 0;        ///< collision elements (a link may have several) and environment
  std::size_t moving_joints = 0;  ///< revolute, continuous and prismatic
  std::size_t frames = 0;
  std::size_t self_pairs = 0;      ///< object pairs of two links the self-collision query asks
  std::size_t adjacent_pairs = 0;  ///< link pairs left out: joined by a joint
  std::size_t touching_pairs = 0;  ///< left out: in contact in MoveIt's default state
  std::size_t disabled_pairs = 0;  ///< left out: --disable-pair
};

/// Reads the robot, its trajectory and its environment and writes the scene file. Self-collision
/// is one group query (all pairs) over every pair of links but adjacent ones and those in
/// contact at the reference configuration (MoveIt's default state), as MoveIt's setup assistant
/// applies those two rules, the pairs left out being its `except` list;
/// robot against environment is one group query of all pairs, and each clearance link (by default
/// the link with the most joints above it) gets a distance query to each environment object, each
/// first-contact link a first_contact query to each. Errors name the file and the link, joint or
/// column.
Result<UrdfImport> importUrdf(const UrdfImportRequest& request);

}  // namespace collido
