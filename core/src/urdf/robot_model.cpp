#include "robot_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <collido/mesh/input_file.h>

namespace collido::urdf_import {
namespace {

namespace fs = std::filesystem;

// Collects urdfdom's messages (it reports through console_bridge) while a parse runs, so that an
// error names what urdfdom named, instead of going to the terminal.
class MessageCollector final : public console_bridge::OutputHandler {
 public:
  MessageCollector() : saved_(console_bridge::getOutputHandler()) {
    console_bridge::useOutputHandler(this);
  }
  // Twice, so that console_bridge's "previous handler" is not left pointing at this one.
  ~MessageCollector() override {
    console_bridge::useOutputHandler(saved_);
    console_bridge::useOutputHandler(saved_);
  }
  MessageCollector(const MessageCollector&) = delete;
  MessageCollector& operator=(const MessageCollector&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/,
           int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors_.push_back(text);
  }
  std::string text() const {
    std::string out;
    for (const std::string& e : errors_)
      out += (out.empty() ? "" : "; ") + e;
    return out.empty() ? "urdfdom could not read it" : out;
  }

 private:
  console_bridge::OutputHandler* saved_;
  std::vector<std::string> errors_;
};

Eigen::Isometry3d poseOf(const urdf::Pose& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  pose.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z)
                      .normalized()
                      .toRotationMatrix();
  return pose;
}

// A joint cycle leaves urdfdom without a root and saying only that; the joints are read again
// (with TinyXML, which urdfdom reads with) to name the links and joints of the cycle.
std::string cycleOf(const std::string& xml) {
  TiXmlDocument document;
  document.Parse(xml.c_str());
  const TiXmlElement* robot = document.RootElement();
  if (robot == nullptr) return "";
  std::map<std::string, std::pair<std::string, std::string>> parent_of;  // child: parent, joint
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const TiXmlElement* parent = joint->FirstChildElement("parent");
    const TiXmlElement* child = joint->FirstChildElement("child");
    const char* name = joint->Attribute("name");
    if (parent == nullptr || child == nullptr || name == nullptr) continue;
    const char* p = parent->Attribute("link");
    const char* c = child->Attribute("link");
    if (p != nullptr && c != nullptr) parent_of[c] = {p, name};
  }
  for (const auto& start : parent_of) {
    std::vector<std::string> path = {start.first};
    std::vector<std::string> joints;
    std::set<std::string> seen = {start.first};
    for (auto at = parent_of.find(start.first); at != parent_of.end();
         at = parent_of.find(at->second.first)) {
      const std::string& parent = at->second.first;
      path.push_back(parent);
      joints.push_back(at->second.second);
      if (parent == start.first) {
        std::string chain;
        for (auto link = path.rbegin(); link != path.rend(); ++link)
          chain += (chain.empty() ? "" : " -> ") + *link;
        std::string through;
        for (auto joint = joints.rbegin(); joint != joints.rend(); ++joint)
          through += (through.empty() ? "'" : ", '") + *joint + "'";
        std::string message = "the joints " + through + " make a cycle of links: ";
        message += chain;
        return message + " (a robot is a tree)";
      }
      if (!seen.insert(parent).second) break;  // a cycle not through `start`: found from it
    }
  }
  return "";
}

// A mesh's filename: "package://PKG/REST" looked for upwards from the URDF's folder (a folder
// PKG holding REST, or a folder named PKG), "file://PATH", or a path relative to the URDF.
std::optional<fs::path> resolveMesh(const std::string& uri, const fs::path& urdf_folder,
                                    std::vector<std::string>& looked) {
  const std::string package = "package://";
  const std::string file = "file://";
  if (uri.rfind(file, 0) == 0) {
    looked.push_back(uri.substr(file.size()));
    return fs::is_regular_file(looked.back()) ? std::optional<fs::path>(looked.back())
                                              : std::nullopt;
  }
  if (uri.rfind(package, 0) != 0) {
    const fs::path path = fs::path(uri).is_absolute() ? fs::path(uri) : urdf_folder / uri;
    looked.push_back(path.string());
    return fs::is_regular_file(path) ? std::optional<fs::path>(path) : std::nullopt;
  }
  const std::string rest = uri.substr(package.size());
  const std::size_t slash = rest.find('/');
  const std::string name = rest.substr(0, slash);
  const std::string inside = slash == std::string::npos ? "" : rest.substr(slash + 1);
  for (fs::path folder = urdf_folder;; folder = folder.parent_path()) {
    for (const fs::path& candidate :
         {folder / name / inside, folder.filename() == name ? folder / inside : fs::path()}) {
      if (candidate.empty()) continue;
      looked.push_back(candidate.string());
      if (fs::is_regular_file(candidate)) return candidate;
    }
    if (folder == folder.parent_path()) break;
  }
  return std::nullopt;
}

Result<Geometry> geometryOf(const urdf::Geometry& g, const std::string& link,
                            const fs::path& urdf_folder, const std::string& label) {
  Geometry out;
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(g);
      out.kind = Geometry::Kind::kBox;
      out.size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(g);
      out.kind = Geometry::Kind::kCylinder;
      out.radius = cylinder.radius;
      out.length = cylinder.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      out.kind = Geometry::Kind::kSphere;
      out.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(g);
      out.kind = Geometry::Kind::kMesh;
      out.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
      if (!(out.scale.minCoeff() > 0.0)) {
        return Status(StatusCode::kInvalidArgument,
                      label + ": link '" + link + "': collision mesh '" + mesh.filename +
                          "': a scale factor is not > 0 (a mirrored mesh is not imported)");
      }
      std::vector<std::string> looked;
      const std::optional<fs::path> found = resolveMesh(mesh.filename, urdf_folder, looked);
      if (!found) {
        std::string places;
        for (const std::string& place : looked)
          places += (places.empty() ? "" : ", ") + place;
        return Status(StatusCode::kInvalidArgument, label + ": link '" + link +
                                                        "': collision mesh '" + mesh.filename +
                                                        "' not found (looked for " + places + ")");
      }
      out.mesh_file = fs::absolute(*found).lexically_normal().string();
      break;
    }
  }
  return out;
}

Result<Joint> jointOf(const urdf::Joint& j, const std::map<std::string, std::size_t>& link_index,
                      const std::string& label) {
  Joint joint;
  joint.name = j.name;
  switch (j.type) {
    case urdf::Joint::FIXED:
      joint.kind = Joint::Kind::kFixed;
      break;
    case urdf::Joint::REVOLUTE:
      joint.kind = Joint::Kind::kRevolute;
      break;
    case urdf::Joint::CONTINUOUS:
      joint.kind = Joint::Kind::kContinuous;
      break;
    case urdf::Joint::PRISMATIC:
      joint.kind = Joint::Kind::kPrismatic;
      break;
    default:
      return Status(StatusCode::kInvalidArgument,
                    label + ": joint '" + j.name +
                        "': floating and planar joints are not imported (revolute, continuous, "
                        "prismatic and fixed are)");
  }
  joint.parent = link_index.at(j.parent_link_name);
  joint.child = link_index.at(j.child_link_name);
  joint.origin = poseOf(j.parent_to_joint_origin_transform);
  const Eigen::Vector3d axis(j.axis.x, j.axis.y, j.axis.z);
  if (joint.moves() && !(axis.norm() > 0.0)) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": joint '" + j.name + "': its axis is zero");
  }
  if (joint.moves()) joint.axis = axis.normalized();
  if (joint.limited()) {
    if (!j.limits || !(j.limits->lower <= j.limits->upper)) {
      return Status(StatusCode::kInvalidArgument,
                    label + ": joint '" + j.name + "': a " +
                        (joint.kind == Joint::Kind::kRevolute ? "revolute" : "prismatic") +
                        " joint needs limits with lower <= upper");
    }
    joint.lower = j.limits->lower;
    joint.upper = j.limits->upper;
  }
  return joint;
}

}  // namespace

double Joint::clamped(double value) const {
  return limited() ? std::clamp(value, lower, upper) : value;
}

template <typename Named>
std::optional<std::size_t> indexNamed(const std::vector<Named>& items, const std::string& wanted) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == wanted) return i;
  }
  return std::nullopt;
}

std::optional<std::size_t> RobotModel::linkNamed(const std::string& wanted) const {
  return indexNamed(links, wanted);
}

std::optional<std::size_t> RobotModel::jointNamed(const std::string& wanted) const {
  return indexNamed(joints, wanted);
}

double RobotModel::valueOf(std::size_t joint, const std::vector<double>& values) const {
  // A mimic follows its joint, which may follow another (readRobot refused cycles).
  const Joint& j = joints[joint];
  return j.mimics ? j.multiplier * valueOf(*j.mimics, values) + j.offset : values[joint];
}

std::vector<Eigen::Isometry3d> RobotModel::linkPoses(const std::vector<double>& values) const {
  std::vector<Eigen::Isometry3d> poses(links.size(), Eigen::Isometry3d::Identity());
  for (const std::size_t link : order) {
    if (!links[link].parent_joint) continue;
    const Joint& joint = joints[*links[link].parent_joint];
    const double q = valueOf(*links[link].parent_joint, values);
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    if (joint.kind == Joint::Kind::kRevolute || joint.kind == Joint::Kind::kContinuous)
      motion.linear() = Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
    if (joint.kind == Joint::Kind::kPrismatic) motion.translation() = q * joint.axis;
    poses[link] = poses[joint.parent] * joint.origin * motion;
  }
  return poses;
}

Result<RobotModel> readRobot(const std::string& path) {
  Result<std::string> xml = readInputFile(path, "URDF file");
  if (!xml.ok()) return xml.status();
  // Cycles first: urdfdom's links hold their children by shared pointer, so it leaks a cyclic
  // robot it refuses, and says only that it found no root.
  if (const std::string cycle = cycleOf(xml.value()); !cycle.empty())
    return Status(StatusCode::kInvalidArgument, path + ": " + cycle);
  urdf::ModelInterfaceSharedPtr model;
  std::string messages;
  {
    MessageCollector collector;
    model = urdf::parseURDF(xml.value());
    messages = collector.text();
  }
  if (!model) return Status(StatusCode::kInvalidArgument, path + ": " + messages);
  RobotModel robot;
  robot.name = model->getName();
  std::map<std::string, std::size_t> link_index;
  for (const auto& [name, link] : model->links_) {
    link_index[name] = robot.links.size();
    robot.links.push_back(Link{name, std::nullopt, {}});
  }
  // Absolute, so that a URDF named without a folder still has ancestors to search.
  const fs::path folder = fs::absolute(path).lexically_normal().parent_path();
  for (const auto& [name, link] : model->links_) {
    for (const urdf::CollisionSharedPtr& collision : link->collision_array) {
      if (!collision || !collision->geometry) continue;
      Result<Geometry> geometry = geometryOf(*collision->geometry, name, folder, path);
      if (!geometry.ok()) return geometry.status();
      robot.links[link_index.at(name)].collisions.push_back(
          Collision{poseOf(collision->origin), std::move(geometry).value()});
    }
  }
  for (const auto& [name, j] : model->joints_) {
    Result<Joint> joint = jointOf(*j, link_index, path);
    if (!joint.ok()) return joint.status();
    Link& child = robot.links[joint.value().child];
    if (child.parent_joint) {
      std::string message = path + ": link '" + child.name + "' is the child of joints '";
      message += robot.joints[*child.parent_joint].name;
      message += "' and '";
      message += name;
      return Status(StatusCode::kInvalidArgument, message + "' (a robot is a tree)");
    }
    child.parent_joint = robot.joints.size();
    robot.joints.push_back(std::move(joint).value());
  }
  for (const auto& [name, j] : model->joints_) {
    if (!j->mimic) continue;
    Joint& joint = robot.joints[*robot.jointNamed(name)];
    joint.mimics = robot.jointNamed(j->mimic->joint_name);
    if (!joint.mimics) {
      std::string message = path + ": joint '";
      message += name;
      message += "' mimics '";
      message += j->mimic->joint_name;
      return Status(StatusCode::kInvalidArgument, message + "', which is not a joint of the robot");
    }
    joint.multiplier = j->mimic->multiplier;
    joint.offset = j->mimic->offset;
  }
  for (const Joint& joint : robot.joints) {
    std::optional<std::size_t> at = joint.mimics;
    for (std::size_t steps = 0; at; at = robot.joints[*at].mimics) {
      if (++steps > robot.joints.size()) {
        return Status(StatusCode::kInvalidArgument,
                      path + ": joint '" + joint.name + "' mimics a joint that mimics it back");
      }
    }
  }
  // Parents first: from the root, child joints in name order.
  std::vector<std::size_t> stack = {link_index.at(model->getRoot()->name)};
  while (!stack.empty()) {
    const std::size_t link = stack.back();
    stack.pop_back();
    robot.order.push_back(link);
    for (auto j = robot.joints.rbegin(); j != robot.joints.rend(); ++j) {
      if (j->parent == link) stack.push_back(j->child);
    }
  }
  // urdfdom checks for one root; a link it did not hang under it is refused, not dropped.
  if (robot.order.size() != robot.links.size()) {
    std::string unreached;
    for (std::size_t link = 0; link < robot.links.size(); ++link) {
      if (std::find(robot.order.begin(), robot.order.end(), link) == robot.order.end())
        unreached += (unreached.empty() ? "'" : ", '") + robot.links[link].name + "'";
    }
    return Status(StatusCode::kInvalidArgument,
                  path + ": links " + unreached + " are not under the root link");
  }
  return robot;
}

}  // namespace collido::urdf_import
