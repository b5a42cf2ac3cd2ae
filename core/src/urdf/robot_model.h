// A URDF robot as the importer needs it: links with their collision geometry, joints with their
// kinematics, and forward kinematics over joint values.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <collido/status.h>

namespace collido::urdf_import {

struct Geometry {
  enum class Kind { kBox, kCylinder, kSphere, kMesh };
  Kind kind = Kind::kBox;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  ///< box sides
  double radius = 0.0;                             ///< cylinder, sphere
  double length = 0.0;                             ///< cylinder, along z
  std::string mesh_file;                           ///< resolved path
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

struct Collision {
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  ///< in the link's frame
  Geometry geometry;
};

struct Link {
  std::string name;
  std::optional<std::size_t> parent_joint;
  std::vector<Collision> collisions;
};

struct Joint {
  enum class Kind { kFixed, kRevolute, kContinuous, kPrismatic };
  std::string name;
  Kind kind = Kind::kFixed;
  std::size_t parent = 0;  ///< link
  std::size_t child = 0;   ///< link
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  ///< unit
  double lower = 0.0;  ///< revolute, prismatic: the limits; continuous: none
  double upper = 0.0;
  /// A mimic joint follows another: value = multiplier * that joint's + offset.
  std::optional<std::size_t> mimics;
  double multiplier = 1.0;
  double offset = 0.0;

  bool moves() const { return kind != Kind::kFixed; }
  bool limited() const { return kind == Kind::kRevolute || kind == Kind::kPrismatic; }
  /// The value nearest `value` within the limits.
  double clamped(double value) const;
};

struct RobotModel {
  std::string name;
  std::vector<Link> links;
  std::vector<Joint> joints;
  std::vector<std::size_t> order;  ///< links, every parent before its children

  std::optional<std::size_t> linkNamed(const std::string& name) const;
  std::optional<std::size_t> jointNamed(const std::string& name) const;
  /// A joint's value: its own, or for a mimic joint the one it follows, scaled and offset.
  double valueOf(std::size_t joint, const std::vector<double>& values) const;
  /// Every link's world pose for joint values (by joint; mimic joints' own are ignored).
  std::vector<Eigen::Isometry3d> linkPoses(const std::vector<double>& values) const;
};

/// Reads a URDF file with urdfdom. Errors name the file and, where urdfdom or the importer can,
/// the link or joint: a missing mesh, an unknown or unsupported joint type, a joint cycle.
Result<RobotModel> readRobot(const std::string& path);

}  // namespace collido::urdf_import
