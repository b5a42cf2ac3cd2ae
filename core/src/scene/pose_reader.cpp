#include "pose_reader.h"

#include <cmath>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include <collido/mesh/triangle_mesh.h>

namespace collido::scene_reading {
namespace {

constexpr double kRotationTolerance = 1e-9;

}  // namespace

Eigen::Matrix3d readRotation(const Reader& r, const Node& node) {
  r.expectObject(node, {"matrix", "quaternion", "axis", "degrees"});
  const bool has_matrix = node.has("matrix");
  const bool has_quaternion = node.has("quaternion");
  const bool has_axis = node.has("axis") || node.has("degrees");
  if (int(has_matrix) + int(has_quaternion) + int(has_axis) != 1) {
    r.fail(node, "give exactly one of matrix, quaternion, or axis + degrees");
  }
  if (has_matrix) {
    const Node m = node.at("matrix");
    r.expectArray(m);
    if (m.value.size() != 3) r.fail(m, "expected 3 rows");
    Eigen::Matrix3d rotation;
    for (int row = 0; row < 3; ++row) {
      rotation.row(row) = r.vector3(m.at(static_cast<std::size_t>(row))).transpose();
    }
    const double drift =
        (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (drift > kRotationTolerance || rotation.determinant() <= 0.0) {
      std::ostringstream text;
      text << "not a rotation: max |R^T R - I| = " << drift << ", det = " << rotation.determinant()
           << " (a pose must be rigid: orthonormal rows, determinant +1, within "
           << kRotationTolerance << ")";
      r.fail(m, text.str());
    }
    return rotation;
  }
  if (has_quaternion) {
    const Node q = node.at("quaternion");
    r.expectArray(q);
    if (q.value.size() != 4) r.fail(q, "expected [w, x, y, z]");
    const Eigen::Quaterniond quaternion(r.number(q.at(0)), r.number(q.at(1)), r.number(q.at(2)),
                                        r.number(q.at(3)));
    if (std::abs(quaternion.norm() - 1.0) > 1e-6) {
      r.fail(q, "not a unit quaternion (norm " + std::to_string(quaternion.norm()) + ")");
    }
    return quaternion.normalized().toRotationMatrix();
  }
  if (!node.has("axis") || !node.has("degrees")) r.fail(node, "axis and degrees go together");
  const Eigen::Vector3d axis = r.vector3(node.at("axis"));
  if (!(axis.norm() > 0.0)) r.fail(node.at("axis"), "the axis must not be zero");
  const double degrees = r.number(node.at("degrees"));
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
}

Pose readPose(const Reader& r, const Node& node) {
  r.expectObject(node, {"translation", "rotation"});
  Pose pose = Pose::Identity();
  if (node.has("translation")) {
    pose.translation() = r.vector3(node.at("translation"));
    // The coordinate limit of mesh vertices holds for where a pose puts them, too.
    for (int k = 0; k < 3; ++k) {
      if (std::abs(pose.translation()[k]) > kMaxCoordinate) {
        std::ostringstream text;
        text << pose.translation()[k] << " is beyond the coordinate limit |t| <= " << kMaxCoordinate
             << " (scenes/README.md)";
        r.fail(node.at("translation").at(static_cast<std::size_t>(k)), text.str());
      }
    }
  }
  if (node.has("rotation")) pose.linear() = readRotation(r, node.at("rotation"));
  return pose;
}

}  // namespace collido::scene_reading
