// The poses of the env/rob peer case (tests/data/peer_cases/fcl_env_rob_poses.json) and the
// points of the peer cases' JSON, shared by the oracle's tests.
#pragma once

#include <nlohmann/json.hpp>

#include <collido/geometry.h>

namespace collido::test {

/// A point written as [x, y, z].
inline Eigen::Vector3d jsonVector(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

/// The pose of one case: "R" (row-major rotation) and "t".
inline Pose peerCasePose(const nlohmann::json& c) {
  Pose pose = Pose::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k)
      pose.linear()(r, k) = c["R"][r][k].get<double>();
  }
  pose.translation() =
      Eigen::Vector3d(c["t"][0].get<double>(), c["t"][1].get<double>(), c["t"][2].get<double>());
  return pose;
}

}  // namespace collido::test
