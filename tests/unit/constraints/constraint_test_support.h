#pragma once

#include <random>
#include <vector>

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

/// A distance query over balls, one per body (its centre in the body's frame): exact distances
/// and closest points, and where balls overlap, the depth along the line of centres.
class BallSeparation : public SeparationQuery {
 public:
  struct Ball {
    Eigen::Vector3d centre;
    double radius;
  };

  explicit BallSeparation(std::vector<Ball> balls) : balls_(std::move(balls)) {}

  /// Whether overlaps are measured (a distance-only query says 0 and nothing more).
  bool reports_depth = true;
  /// The query fails from this call on (counting from 1); 0: never.
  int fail_from_call = 0;
  int calls = 0;

  Result<Separation> measure(int body_a, const Pose& pose_a, int body_b,
                             const Pose& pose_b) override {
    ++calls;
    if (fail_from_call > 0 && calls >= fail_from_call) {
      return Status(StatusCode::kInternal, "the engine crashed");
    }
    const Ball& a = balls_[body_a];
    const Ball& b = balls_[body_b];
    const Eigen::Vector3d centre_a = pose_a * a.centre;
    const Eigen::Vector3d centre_b = pose_b * b.centre;
    const Eigen::Vector3d towards_b = (centre_b - centre_a).normalized();
    const double gap = (centre_b - centre_a).norm() - a.radius - b.radius;
    Separation s;
    s.point_a = centre_a + a.radius * towards_b;
    s.point_b = gap > 0.0 ? Eigen::Vector3d(centre_b - b.radius * towards_b) : s.point_a;
    s.distance = std::max(gap, 0.0);
    if (gap < 0.0 && reports_depth) {
      s.depth = -gap;
      s.normal = towards_b;
      s.contact = s.point_a;
    }
    return s;
  }

 private:
  std::vector<Ball> balls_;
};

}  // namespace collido::constraints::testing
