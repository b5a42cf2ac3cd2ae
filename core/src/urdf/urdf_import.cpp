#include <collido/urdf/urdf_import.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include <nlohmann/json.hpp>

#include <collido/io/files.h>
#include <collido/io/scene_pose.h>
#include <collido/mesh/mesh_io.h>
#include <collido/mesh/procedural.h>
#include <collido/oracle/exact_oracle.h>

#include "robot_model.h"
#include "trajectory.h"

namespace collido {
namespace {

using Json = nlohmann::json;
using urdf_import::Geometry;
using urdf_import::RobotModel;
namespace fs = std::filesystem;

// One object of the scene: a link's collision element, or an environment mesh.
struct SceneObjectPlan {
  std::string name;
  std::optional<std::size_t> link;
  Json shape;
  std::shared_ptr<const TriangleMesh> mesh;  // robot objects: for the reference contacts
  std::vector<Eigen::Isometry3d> world;      // per frame
  Eigen::Isometry3d reference = Eigen::Isometry3d::Identity();
  std::optional<std::size_t> parent;  // object index
};

std::string relativePath(const std::string& file, const fs::path& folder) {
  // Lexical, as the scene loader joins them: a symbolic link in between is kept, not resolved.
  return fs::absolute(file)
      .lexically_normal()
      .lexically_relative(folder.lexically_normal())
      .generic_string();
}

// The scene shape of a collision element and its mesh; errors name the link.
Result<std::pair<Json, TriangleMesh>> shapeOf(const Geometry& g, const std::string& link,
                                              const fs::path& folder, const std::string& label) {
  Result<TriangleMesh> mesh = Status(StatusCode::kInternal, "no geometry");
  Json shape;
  switch (g.kind) {
    case Geometry::Kind::kBox:
      shape = {{"generator", "box"}, {"size", {g.size.x(), g.size.y(), g.size.z()}}};
      mesh = makeBox(BoxParams{g.size});
      break;
    case Geometry::Kind::kCylinder: {
      CylinderParams params;
      params.radius = g.radius;
      params.height = g.length;
      shape = {{"generator", "cylinder"}, {"radius", g.radius}, {"height", g.length}};
      mesh = makeCylinder(params);
      break;
    }
    case Geometry::Kind::kSphere: {
      SphereParams params;
      params.radius = g.radius;
      shape = {{"generator", "sphere"}, {"radius", g.radius}};
      mesh = makeSphere(params);
      break;
    }
    case Geometry::Kind::kMesh:
      shape = {{"mesh", relativePath(g.mesh_file, folder)}};
      if (g.scale != Eigen::Vector3d::Ones())
        shape["scale"] = {g.scale.x(), g.scale.y(), g.scale.z()};
      mesh = loadMesh(g.mesh_file);
      if (mesh.ok()) mesh.value().vertices = g.scale.asDiagonal() * mesh.value().vertices;
      break;
  }
  if (!mesh.ok()) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": link '" + link + "': " + mesh.status().message());
  }
  return std::make_pair(std::move(shape), std::move(mesh).value());
}

// The link's nearest ancestor with collision geometry.
std::optional<std::size_t> geometricAncestor(const RobotModel& robot, std::size_t link) {
  for (std::optional<std::size_t> joint = robot.links[link].parent_joint; joint;
       joint = robot.links[robot.joints[*joint].parent].parent_joint) {
    const std::size_t parent = robot.joints[*joint].parent;
    if (!robot.links[parent].collisions.empty()) return parent;
  }
  return std::nullopt;
}

std::pair<std::size_t, std::size_t> ordered(std::size_t a, std::size_t b) {
  return {std::min(a, b), std::max(a, b)};
}

// Link pairs joined by a joint, where a link without geometry joins all its neighbours to each
// other (repeatedly), as MoveIt's setup assistant builds its connection graph: two fingers on a
// bare flange are adjacent, and so are the first links under a bare world link.
std::set<std::pair<std::size_t, std::size_t>> adjacentLinks(const RobotModel& robot) {
  std::vector<std::set<std::size_t>> neighbours(robot.links.size());
  for (const urdf_import::Joint& joint : robot.joints) {
    neighbours[joint.parent].insert(joint.child);
    neighbours[joint.child].insert(joint.parent);
  }
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t link = 0; link < robot.links.size(); ++link) {
      if (!robot.links[link].collisions.empty()) continue;
      for (const std::size_t a : neighbours[link]) {
        for (const std::size_t b : neighbours[link]) {
          if (a != b && neighbours[a].insert(b).second) changed = true;
        }
      }
    }
  }
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < robot.links.size(); ++a) {
    for (const std::size_t b : neighbours[a]) {
      if (!robot.links[a].collisions.empty() && !robot.links[b].collisions.empty())
        pairs.insert(ordered(a, b));
    }
  }
  return pairs;
}

// The link pairs a --disable-pair or --enable-pair list names; errors name an unknown link.
Result<std::set<std::pair<std::size_t, std::size_t>>> linkPairs(
    const std::vector<std::pair<std::string, std::string>>& names, const RobotModel& robot,
    const char* option) {
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& [a, b] : names) {
    const std::optional<std::size_t> la = robot.linkNamed(a);
    const std::optional<std::size_t> lb = robot.linkNamed(b);
    if (!la || !lb) {
      std::string message = option;
      message += " " + a;
      message += " " + b;
      message += ": '";
      message += la ? b : a;
      return Status(StatusCode::kInvalidArgument,
                    message + "' is no link of robot '" + robot.name + "'");
    }
    pairs.insert(ordered(*la, *lb));
  }
  return pairs;
}

class SceneBuilder {
 public:
  SceneBuilder(const UrdfImportRequest& request, const RobotModel& robot)
      : request_(request), robot_(robot) {}

  Status addRobot(const urdf_import::Trajectory& frames) {
    std::vector<std::vector<Eigen::Isometry3d>> link_poses;
    for (const std::vector<double>& values : frames)
      link_poses.push_back(robot_.linkPoses(values));
    const std::vector<Eigen::Isometry3d> reference =
        robot_.linkPoses(urdf_import::referenceConfiguration(robot_));
    for (const std::size_t link : robot_.order) {
      const urdf_import::Link& l = robot_.links[link];
      for (std::size_t k = 0; k < l.collisions.size(); ++k) {
        Result<std::pair<Json, TriangleMesh>> shape =
            shapeOf(l.collisions[k].geometry, l.name, folder(), request_.urdf);
        if (!shape.ok()) return shape.status();
        SceneObjectPlan o;
        o.name = uniqueName(k == 0 ? l.name : l.name + "_" + std::to_string(k + 1));
        o.link = link;
        o.shape = std::move(shape.value().first);
        o.mesh = std::make_shared<const TriangleMesh>(std::move(shape.value().second));
        for (const std::vector<Eigen::Isometry3d>& poses : link_poses)
          o.world.push_back(poses[link] * l.collisions[k].origin);
        o.reference = reference[link] * l.collisions[k].origin;
        // Mounted on its link's first element, else its nearest ancestor's, else the robot's
        // first object, so that the robot is one subtree.
        if (k > 0) {
          o.parent = first_of_link_.at(link);
        } else if (const std::optional<std::size_t> up = geometricAncestor(robot_, link)) {
          o.parent = first_of_link_.at(*up);
        } else if (!objects_.empty()) {
          o.parent = 0;
        }
        if (k == 0) first_of_link_[link] = objects_.size();
        objects_.push_back(std::move(o));
      }
    }
    if (objects_.empty()) {
      return Status(StatusCode::kInvalidArgument, request_.urdf + ": no link of robot '" +
                                                      robot_.name + "' has collision geometry");
    }
    robot_objects_ = objects_.size();
    return {};
  }

  Status addEnvironment(std::size_t frames) {
    for (const EnvironmentMesh& environment : request_.environment) {
      Result<TriangleMesh> mesh = loadMesh(environment.file);
      if (!mesh.ok()) return mesh.status();
      SceneObjectPlan o;
      o.name = uniqueName("env_" + fs::path(environment.file).stem().string());
      o.shape = {{"mesh", relativePath(environment.file, folder())}};
      o.world.assign(frames, environment.pose);
      if (objects_.size() > robot_objects_) o.parent = robot_objects_;
      objects_.push_back(std::move(o));
    }
    return {};
  }

  // Self-collision: every pair of links with geometry but adjacent ones, those in contact at the
  // reference configuration and disabled ones (enabled ones whatever the rules): the object
  // pairs of one group query over the robot.
  Status addSelfCollision(UrdfImport& summary) {
    Result<std::set<std::pair<std::size_t, std::size_t>>> disabled =
        linkPairs(request_.disable_pairs, robot_, "--disable-pair");
    if (!disabled.ok()) return disabled.status();
    Result<std::set<std::pair<std::size_t, std::size_t>>> enabled =
        linkPairs(request_.enable_pairs, robot_, "--enable-pair");
    if (!enabled.ok()) return enabled.status();
    const std::set<std::pair<std::size_t, std::size_t>> adjacent = adjacentLinks(robot_);
    std::vector<std::size_t> links;
    for (const std::size_t link : robot_.order) {
      if (!robot_.links[link].collisions.empty()) links.push_back(link);
    }
    std::set<std::pair<std::size_t, std::size_t>> asked;  // object pairs
    for (std::size_t i = 0; i < links.size(); ++i) {
      for (std::size_t j = i + 1; j < links.size(); ++j) {
        const auto pair = ordered(links[i], links[j]);
        const bool forced = enabled.value().count(pair) != 0;
        if (!forced && disabled.value().count(pair) != 0) {
          ++summary.disabled_pairs;
          continue;
        }
        if (!forced && adjacent.count(pair) != 0) {
          ++summary.adjacent_pairs;
          continue;
        }
        if (!forced && touchAtReference(links[i], links[j])) {
          ++summary.touching_pairs;
          continue;
        }
        for (const std::size_t a : objectsOf(links[i])) {
          for (const std::size_t b : objectsOf(links[j]))
            asked.insert(ordered(a, b));
        }
      }
    }
    summary.self_pairs = asked.size();
    if (asked.empty()) return {};
    // One group query over the robot, as a planner asks it of a state, with the pairs left out
    // (and those of one link's elements) as its allowed-collision list.
    Json except = Json::array();
    for (std::size_t a = 0; a < robot_objects_; ++a) {
      for (std::size_t b = a + 1; b < robot_objects_; ++b) {
        if (asked.count({a, b}) == 0) except.push_back({objects_[a].name, objects_[b].name});
      }
    }
    queries_.push_back({{"name", "self-collision"},
                        {"among", {{{"subtree", objects_[0].name}}}},
                        {"except", std::move(except)},
                        {"kind", "all_pairs"}});
    return {};
  }

  // The robot against its environment (one group query of all pairs); the clearance of each
  // link --clearance names (by default the last link of the longest chain) to each environment
  // object; and the first contact over each step of each link --first-contact names with each
  // environment object (a planner's edge check between waypoints). Errors name the option and a
  // link that is unknown or has no collision geometry.
  Status addEnvironmentQueries() {
    if (objects_.size() == robot_objects_) return {};
    queries_.push_back({{"name", "robot vs environment"},
                        {"a", {{"subtree", objects_[0].name}}},
                        {"b", {{"subtree", objects_[robot_objects_].name}}},
                        {"kind", "all_pairs"}});
    Result<std::vector<std::size_t>> measured =
        linkObjects(request_.clearance_links, "--clearance");
    if (!measured.ok()) return measured.status();
    if (measured.value().empty()) measured.value().push_back(deepestLinkObject());
    addLinkQueries(measured.value(), "clearance: ", "distance");
    const Result<std::vector<std::size_t>> moving =
        linkObjects(request_.first_contact_links, "--first-contact");
    if (!moving.ok()) return moving.status();
    addLinkQueries(moving.value(), "first contact: ", "first_contact");
    return {};
  }

  // The first object of each named link, in the order named.
  Result<std::vector<std::size_t>> linkObjects(const std::vector<std::string>& names,
                                               const std::string& option) const {
    std::vector<std::size_t> firsts;
    for (const std::string& name : names) {
      std::string problem = option;
      problem += " ";
      problem += name;
      const std::optional<std::size_t> link = robot_.linkNamed(name);
      if (!link) {
        problem += ": no link of robot '" + robot_.name + "'";
        return Status(StatusCode::kInvalidArgument, problem);
      }
      const auto first = first_of_link_.find(*link);
      if (first == first_of_link_.end()) {
        problem += ": link has no collision geometry";
        return Status(StatusCode::kInvalidArgument, problem);
      }
      firsts.push_back(first->second);
    }
    return firsts;
  }

  // One query of `kind` between each of `links` and each environment object.
  void addLinkQueries(const std::vector<std::size_t>& links, const std::string& prefix,
                      const char* kind) {
    for (const std::size_t link : links) {
      for (std::size_t e = robot_objects_; e < objects_.size(); ++e) {
        queries_.push_back({{"name", prefix + objects_[link].name + "-" + objects_[e].name},
                            {"a", objects_[link].name},
                            {"b", objects_[e].name},
                            {"kind", kind}});
      }
    }
  }

  // The first object of the link with the most joints above it (the tool, on an arm).
  std::size_t deepestLinkObject() const {
    std::size_t tool = 0;
    std::size_t deepest = 0;
    for (const auto& [link, first] : first_of_link_) {
      std::size_t depth = 0;
      for (std::optional<std::size_t> j = robot_.links[link].parent_joint; j;
           j = robot_.links[robot_.joints[*j].parent].parent_joint)
        ++depth;
      if (depth > deepest || (depth == deepest && first < tool)) {
        deepest = depth;
        tool = first;
      }
    }
    return tool;
  }

  Json scene(std::size_t frames, const std::string& description) const {
    Json objects = Json::array();
    for (const SceneObjectPlan& o : objects_) {
      Json object = {{"name", o.name}, {"shape", o.shape}};
      std::vector<Eigen::Isometry3d> relative;
      for (std::size_t f = 0; f < frames; ++f) {
        relative.push_back(o.parent ? objects_[*o.parent].world[f].inverse() * o.world[f]
                                    : o.world[f]);
      }
      if (o.parent) object["parent"] = objects_[*o.parent].name;
      // Fixed on its parent up to rounding (a second element, a fixed joint): one pose.
      const bool still = std::all_of(relative.begin(), relative.end(), [&](const auto& p) {
        return (p.matrix() - relative[0].matrix()).cwiseAbs().maxCoeff() <= 1e-14;
      });
      if (still) {
        object["pose"] = io::scenePoseJson(relative[0]);
      } else {
        Json poses = Json::array();
        for (const Eigen::Isometry3d& p : relative)
          poses.push_back(io::scenePoseJson(p));
        object["motion"] = {{"poses", std::move(poses)}};
      }
      objects.push_back(std::move(object));
    }
    // No "name": the scene is named after its file (robot_cell.json: robot_cell), the robot in
    // the description.
    return {{"description", description},
            {"up", {0, 0, 1}},  // URDF's world is z up (ROS's REP 103)
            {"frames", frames},
            {"objects", std::move(objects)},
            {"queries", queries_}};
  }

  // Only the first-contact queries (--first-contact-only): a planner's edge checks alone.
  void keepFirstContactsOnly() {
    Json kept = Json::array();
    for (const Json& query : queries_) {
      if (query.at("kind") == "first_contact") kept.push_back(query);
    }
    queries_ = std::move(kept);
  }

  bool hasQueries() const { return !queries_.empty(); }
  std::size_t objectCount() const { return objects_.size(); }

 private:
  fs::path folder() const { return fs::absolute(request_.output).parent_path(); }

  std::string uniqueName(const std::string& wanted) {
    std::string name = wanted;
    for (int copy = 2; !names_.insert(name).second; ++copy)
      name = wanted + "_" + std::to_string(copy);
    return name;
  }

  std::vector<std::size_t> objectsOf(std::size_t link) const {
    std::vector<std::size_t> out;
    for (std::size_t o = 0; o < robot_objects_; ++o) {
      if (objects_[o].link == link) out.push_back(o);
    }
    return out;
  }

  bool touchAtReference(std::size_t link_a, std::size_t link_b) const {
    for (const std::size_t a : objectsOf(link_a)) {
      for (const std::size_t b : objectsOf(link_b)) {
        const SceneObjectPlan& oa = objects_[a];
        const SceneObjectPlan& ob = objects_[b];
        if (exactIntersectingPairs(*oa.mesh, oa.reference, *ob.mesh, ob.reference,
                                   OracleMode::kFirstPair)
                .intersecting)
          return true;
      }
    }
    return false;
  }

  const UrdfImportRequest& request_;
  const RobotModel& robot_;
  std::vector<SceneObjectPlan> objects_;
  std::size_t robot_objects_ = 0;
  std::map<std::size_t, std::size_t> first_of_link_;
  std::set<std::string> names_;
  Json queries_ = Json::array();
};

}  // namespace

Result<UrdfImport> importUrdf(const UrdfImportRequest& request) {
  Result<RobotModel> robot = urdf_import::readRobot(request.urdf);
  if (!robot.ok()) return robot.status();
  Result<urdf_import::Trajectory> frames =
      request.trajectory.empty() ? Result<urdf_import::Trajectory>(urdf_import::randomTrajectory(
                                       robot.value(), request.frames, request.seed))
                                 : urdf_import::readTrajectory(request.trajectory, robot.value());
  if (!frames.ok()) return frames.status();
  if (frames.value().empty())
    return Status(StatusCode::kInvalidArgument, "--frames: a scene needs at least one frame");

  UrdfImport summary;
  summary.robot = robot.value().name;
  summary.frames = frames.value().size();
  for (const urdf_import::Joint& joint : robot.value().joints)
    summary.moving_joints += joint.moves() && !joint.mimics ? 1 : 0;
  SceneBuilder builder(request, robot.value());
  if (Status s = builder.addRobot(frames.value()); !s.ok()) return s;
  if (Status s = builder.addEnvironment(summary.frames); !s.ok()) return s;
  if (Status s = builder.addSelfCollision(summary); !s.ok()) return s;
  if (Status s = builder.addEnvironmentQueries(); !s.ok()) return s;
  if (request.first_contact_only) {
    if (request.first_contact_links.empty()) {
      return Status(StatusCode::kInvalidArgument,
                    "--first-contact-only: no --first-contact link to ask");
    }
    builder.keepFirstContactsOnly();
  }
  if (!builder.hasQueries()) {
    return Status(StatusCode::kInvalidArgument,
                  request.urdf +
                      ": nothing to ask: no pair of links is left for self-collision "
                      "and no --environment was given");
  }
  summary.objects = builder.objectCount();
  const std::string source =
      request.trajectory.empty()
          ? std::to_string(summary.frames) + " seeded random configurations (seed " +
                std::to_string(request.seed) + ")"
          : "the trajectory " + fs::path(request.trajectory).filename().string();
  std::string description = "Robot '" + summary.robot + "' imported from " +
                            fs::path(request.urdf).filename().string() +
                            " by collido import urdf: " + source;
  for (std::size_t e = 0; e < request.environment.size(); ++e) {
    description += e == 0 ? "; its environment: " : ", ";
    description += fs::path(request.environment[e].file).filename().string();
  }
  description += ".";
  std::error_code error;
  fs::create_directories(fs::absolute(request.output).parent_path(), error);
  if (Status s = io::writeFileAtomically(request.output,
                                         builder.scene(summary.frames, description).dump(1) + "\n");
      !s.ok())
    return s;
  return summary;
}

}  // namespace collido
