#include <collido/io/scene_pose.h>

namespace collido::io {

nlohmann::json scenePoseJson(const Pose& pose) {
  const Eigen::Vector3d t = pose.translation();
  nlohmann::json out = {{"translation", {t.x(), t.y(), t.z()}}};
  const Eigen::Matrix3d r = pose.linear();
  if (r == Eigen::Matrix3d::Identity()) return out;
  out["rotation"] = {
      {"matrix",
       {{r(0, 0), r(0, 1), r(0, 2)}, {r(1, 0), r(1, 1), r(1, 2)}, {r(2, 0), r(2, 1), r(2, 2)}}}};
  return out;
}

}  // namespace collido::io
