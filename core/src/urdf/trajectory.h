// The joint values of every frame: a joints CSV, or seeded random configurations.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <collido/status.h>

#include "robot_model.h"

namespace collido::urdf_import {

/// Per frame, a value per joint (by joint index; fixed and mimic joints' unused).
using Trajectory = std::vector<std::vector<double>>;

/// The reference configuration (MoveIt's default state): every moving joint at 0, or at the
/// middle of its limits when they exclude 0.
std::vector<double> referenceConfiguration(const RobotModel& robot);

/// Reads a joints CSV: a header of joint names (moving, not mimic), then one row of values per
/// frame (radians, metres); joints not named stay at the reference. Errors name the file, and the
/// row and column: a name that is no joint, a value that is not a number or is beyond the limits.
Result<Trajectory> readTrajectory(const std::string& path, const RobotModel& robot);

/// `frames` configurations, each joint uniform within its limits (a continuous joint in
/// [-pi, pi]), from `seed`.
Trajectory randomTrajectory(const RobotModel& robot, std::size_t frames, std::uint64_t seed);

}  // namespace collido::urdf_import
