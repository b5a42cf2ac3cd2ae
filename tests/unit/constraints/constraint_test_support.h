#pragma once

#include <random>

#include <Eigen/Geometry>

#include <collido/constraints/problem.h>

namespace collido::constraints::testing {

/// Eigen's `{}` leaves a vector uninitialised: name the origin instead.
inline const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();

/// A pose with a random rotation and a translation within ±spread.
inline Pose randomPose(std::mt19937_64& random, double spread) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-spread, spread);
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  Pose pose = Pose::Identity();
  pose.linear() = q.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
  return pose;
}

inline Eigen::Vector3d randomVector(std::mt19937_64& random, double spread) {
  std::uniform_real_distribution<double> uniform(-spread, spread);
  return {uniform(random), uniform(random), uniform(random)};
}

/// A body's pose after solving, moved by rotating its start by `turn` and translating.
inline double rotationAngleBetween(const Pose& a, const Pose& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

}  // namespace collido::constraints::testing
