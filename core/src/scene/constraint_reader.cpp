#include "constraint_reader.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <collido/constraints/solve.h>
#include <collido/oracle/distance_oracle.h>

#include "oracle_separation.h"
#include "placement_store.h"

namespace collido::scene_reading {
namespace {

using constraints::Axis;
using constraints::DirectionRef;
using constraints::Plane;
using constraints::PointRef;
using constraints::Problem;
using constraints::Target;

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

/// The largest distance of a vertex of the object's frame-0 shape from its origin: how far a
/// turn of one radian moves its points.
double boundingRadius(const SceneObject& object) {
  const std::shared_ptr<const TriangleMesh> shape = object.shapeAt(0);  // may be made here
  return shape->vertices.cols() == 0 ? 0.0 : shape->vertices.colwise().norm().maxCoeff();
}

/// Reads the block into a Problem, creating a body for each object the first time a constraint
/// names it.
class BlockReader {
 public:
  BlockReader(const Reader& r, const std::vector<ObjectMotionSource>& sources, Scene& scene,
              Problem& problem)
      : r_(r), sources_(sources), scene_(scene), problem_(problem) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      object_index_.emplace(scene.objects[i].name, i);
  }

  void readFixed(const Node& list) {
    r_.expectArray(list);
    for (std::size_t k = 0; k < list.value.size(); ++k) {
      const int body = bodyOf(list.at(k), true);
      check(list.at(k), problem_.fixBody(body));
    }
  }

  void readVariables(const Node& list) {
    r_.expectArray(list);
    for (std::size_t k = 0; k < list.value.size(); ++k) {
      const Node node = list.at(k);
      r_.expectObject(node, {"name", "value", "scale", "fixed"});
      if (!node.has("name")) r_.fail(node, "missing 'name'");
      if (!node.has("value")) r_.fail(node, "missing 'value'");
      const std::string name = r_.string(node.at("name"));
      const Result<int> variable = problem_.addVariable(
          name, r_.number(node.at("value")), r_.positive(node, "scale", problem_.lengthScale()));
      check(node, variable.ok() ? Status() : variable.status());
      if (node.has("fixed")) {
        if (!node.at("fixed").value.is_boolean())
          r_.fail(node.at("fixed"), "expected true or false");
        if (node.at("fixed").value.get<bool>()) check(node, problem_.fixVariable(variable.value()));
      }
      variable_index_.emplace(name, variable.value());
    }
  }

  void readConstraint(const Node& node, std::size_t index) {
    if (!node.value.is_object() || !node.has("type")) r_.fail(node, "missing 'type'");
    const std::string type = r_.string(node.at("type"));
    const std::string name =
        node.has("name") ? r_.string(node.at("name")) : type + " " + std::to_string(index);
    Result<int> added = Status(StatusCode::kInvalidArgument, "");
    if (type == "coincident") {
      r_.expectObject(node, {"type", "name", "p", "q"});
      added = problem_.addCoincident(name, point(node, "p"), point(node, "q"));
    } else if (type == "point_on_plane") {
      r_.expectObject(node, {"type", "name", "p", "plane"});
      const Axis plane = axis(node, "plane", "normal");
      added = problem_.addPointOnPlane(name, point(node, "p"), Plane{plane.point, plane.direction});
    } else if (type == "point_on_line") {
      r_.expectObject(node, {"type", "name", "p", "line"});
      added = problem_.addPointOnLine(name, point(node, "p"), axis(node, "line", "direction"));
    } else if (type == "distance") {
      r_.expectObject(node, {"type", "name", "p", "q", "value", "variable"});
      added = problem_.addDistance(name, point(node, "p"), point(node, "q"), target(node, 1.0));
    } else if (type == "angle") {
      r_.expectObject(node, {"type", "name", "d", "e", "degrees", "variable"});
      added = problem_.addAngle(name, direction(node, "d"), direction(node, "e"),
                                target(node, kRadiansPerDegree));
    } else if (type == "parallel" || type == "perpendicular") {
      r_.expectObject(node, {"type", "name", "d", "e"});
      added = type == "parallel"
                  ? problem_.addParallel(name, direction(node, "d"), direction(node, "e"))
                  : problem_.addPerpendicular(name, direction(node, "d"), direction(node, "e"));
    } else if (type == "coaxial") {
      r_.expectObject(node, {"type", "name", "a", "b"});
      added = problem_.addCoaxial(name, axis(node, "a", "direction"), axis(node, "b", "direction"));
    } else if (type == "clearance") {
      r_.expectObject(node, {"type", "name", "a", "b", "value", "variable"});
      for (const char* side : {"a", "b"}) {
        if (!node.has(side)) r_.fail(node, std::string("missing '") + side + "'");
      }
      const int a = bodyOf(node.at("a"), false);
      const int b = bodyOf(node.at("b"), false);
      added = problem_.addClearance(name, a, b, target(node, 1.0));
    } else {
      r_.fail(node.at("type"), "unknown constraint type '" + type +
                                   "' (coincident, point_on_plane, point_on_line, distance, "
                                   "angle, parallel, perpendicular, coaxial, clearance)");
    }
    check(node, added.ok() ? Status() : added.status());
    if (type == "clearance") clearances_.push_back(added.value());
  }

  /// Objects the solve may move must have motions a rigid correction keeps.
  void checkMovable() const {
    for (const auto& [body, node] : movable_check_) {
      if (problem_.bodies()[body].fixed) continue;
      const ObjectMotionSource& source = sources_[object_of_body_[body]];
      std::string why;
      std::string remedy = "list it under 'fixed', or give it a pose, keyframes or a linear motion";
      if (source.has_parent || source.has_children) {
        // A correction of one object of a hierarchy would have to be carried through the
        // relative poses of the others, which the solve does not model.
        why = source.has_parent ? "it is mounted on a parent, whose motion it follows"
                                : "objects are mounted on it, which would have to move with it";
        remedy = "list it under 'fixed' (the solve moves objects outside hierarchies only)";
      } else if (source.tracked) {
        why = "its poses are recovered from markers";
      } else if (source.referenced) {
        why = "another object's random motion is placed relative to it";
      } else if (source.draped) {
        why = "it drapes onto another object, its stops cast against the poses before the solve";
      } else if (source.drape_target) {
        why = "another object drapes onto it, its stops cast against the poses before the solve";
      } else if (source.kind == "random" || source.kind == "jitter") {
        why = "its motion is " + source.kind + " about a base pose";
      }
      if (!why.empty()) {
        std::string message = "the constraints would move object '";
        message += problem_.bodies()[body].name;
        message += "', but " + why;
        message += ": " + remedy;
        r_.fail(node, message);
      }
    }
  }

  const std::vector<int>& clearances() const { return clearances_; }

  /// The object behind each body, in body order.
  const std::vector<std::size_t>& objectOfBody() const { return object_of_body_; }

 private:
  void check(const Node& node, const Status& status) const {
    if (!status.ok()) r_.fail(node, status.message());
  }

  /// The body of the object `name_node` names, created on first use; `fixing`: the object is
  /// listed under 'fixed', so any motion is fine.
  int bodyOf(const Node& name_node, bool fixing) {
    const std::string name = r_.string(name_node);
    const auto found = object_index_.find(name);
    if (found == object_index_.end()) r_.fail(name_node, "no object named '" + name + "'");
    const std::size_t object = found->second;
    const auto known = std::find(object_of_body_.begin(), object_of_body_.end(), object);
    if (known != object_of_body_.end()) return static_cast<int>(known - object_of_body_.begin());
    const SceneObject& o = scene_.objects[object];
    const double radius = std::max(boundingRadius(o), 1e-9 * problem_.lengthScale());
    const Result<int> body = problem_.addBody(name, o.poseAt(0), radius);
    check(name_node, body.ok() ? Status() : body.status());
    object_of_body_.push_back(object);
    if (!fixing) movable_check_.emplace_back(body.value(), name_node);
    return body.value();
  }

  int objectBody(const Node& ref) {
    return ref.has("object") ? bodyOf(ref.at("object"), false) : constraints::kWorld;
  }

  PointRef point(const Node& parent, const char* key) {
    if (!parent.has(key)) r_.fail(parent, std::string("missing '") + key + "'");
    const Node ref = parent.at(key);
    r_.expectObject(ref, {"object", "at"});
    if (!ref.has("at")) r_.fail(ref, "missing 'at'");
    return PointRef{objectBody(ref), r_.vector3(ref.at("at"))};
  }

  DirectionRef direction(const Node& parent, const char* key) {
    if (!parent.has(key)) r_.fail(parent, std::string("missing '") + key + "'");
    const Node ref = parent.at(key);
    r_.expectObject(ref, {"object", "direction"});
    if (!ref.has("direction")) r_.fail(ref, "missing 'direction'");
    return DirectionRef{objectBody(ref), r_.vector3(ref.at("direction"))};
  }

  /// A line, an axis or a plane: a point "at" and a direction under `direction_key`.
  Axis axis(const Node& parent, const char* key, const char* direction_key) {
    if (!parent.has(key)) r_.fail(parent, std::string("missing '") + key + "'");
    const Node ref = parent.at(key);
    r_.expectObject(ref, {"object", "at", direction_key});
    for (const char* field : {"at", direction_key}) {
      if (!ref.has(field)) r_.fail(ref, std::string("missing '") + field + "'");
    }
    const int body = objectBody(ref);
    return Axis{PointRef{body, r_.vector3(ref.at("at"))},
                DirectionRef{body, r_.vector3(ref.at(direction_key))}};
  }

  /// A dimension: a constant ("value", or "degrees" for an angle, times `unit`) or a variable.
  Target target(const Node& node, double unit) {
    const char* constant = unit == 1.0 ? "value" : "degrees";
    if (node.has(constant) == node.has("variable")) {
      r_.fail(node, std::string("give exactly one of '") + constant + "' and 'variable'");
    }
    if (node.has(constant)) return Target{r_.number(node.at(constant)) * unit, -1};
    const std::string name = r_.string(node.at("variable"));
    const auto found = variable_index_.find(name);
    if (found == variable_index_.end()) {
      r_.fail(node.at("variable"), "no variable named '" + name + "' in /constraints/variables");
    }
    return Target{0.0, found->second};
  }

  const Reader& r_;
  const std::vector<ObjectMotionSource>& sources_;
  Scene& scene_;
  Problem& problem_;
  std::map<std::string, std::size_t> object_index_;
  std::map<std::string, int> variable_index_;
  std::vector<std::size_t> object_of_body_;
  std::vector<std::pair<int, Node>> movable_check_;  ///< bodies not fixed on first mention
  std::vector<int> clearances_;                      ///< indices of the clearance constraints
};

}  // namespace

void solveSceneConstraints(const Reader& r, const Node& block,
                           const std::vector<ObjectMotionSource>& sources,
                           const std::string& placement_store, Scene& scene) {
  r.expectObject(block,
                 {"length_scale", "tolerance", "allow_redundant", "fixed", "variables", "list"});
  double largest = 0.0;
  for (const SceneObject& object : scene.objects)
    largest = std::max(largest, boundingRadius(object));
  Problem problem(r.positive(block, "length_scale", largest > 0.0 ? largest : 1.0));
  constraints::SolveOptions options;
  options.tolerance = r.positive(block, "tolerance", options.tolerance);
  if (block.has("allow_redundant")) {
    if (!block.at("allow_redundant").value.is_boolean()) {
      r.fail(block.at("allow_redundant"), "expected true or false");
    }
    options.allow_redundant = block.at("allow_redundant").value.get<bool>();
  }
  BlockReader reader(r, sources, scene, problem);
  if (block.has("fixed")) reader.readFixed(block.at("fixed"));
  if (block.has("variables")) reader.readVariables(block.at("variables"));
  if (!block.has("list")) r.fail(block, "missing 'list'");
  const Node list = block.at("list");
  r.expectArray(list);
  if (list.value.empty()) r.fail(list, "the list holds no constraint");
  for (std::size_t k = 0; k < list.value.size(); ++k)
    reader.readConstraint(list.at(k), k);
  reader.checkMovable();

  std::vector<std::shared_ptr<const TriangleMesh>> meshes;
  for (std::size_t object : reader.objectOfBody())
    meshes.push_back(scene.objects[object].shapeAt(0));
  problem.setSeparationQuery(std::make_shared<OracleSeparation>(meshes));
  const std::vector<constraints::Body> before = problem.bodies();

  // The same block on the same bodies was solved before by another process of this run.
  std::string stored_path;
  std::optional<StoredSolve> solve;
  if (!placement_store.empty()) {
    PlacementKey key(block.value.dump(), largest);
    for (std::size_t body = 0; body < before.size(); ++body)
      key.addBody(before[body].pose, *meshes[body]);
    stored_path = key.path(placement_store);
    solve = readStoredSolve(stored_path, before.size(), problem.variables().size(),
                            reader.clearances().size());
  }
  const bool solved_here = !solve;
  if (solved_here) {
    const Result<constraints::SolveReport> report = constraints::solve(problem, options);
    if (!report.ok()) r.fail(list, "the constraints cannot be met: " + report.status().message());
    solve.emplace();
    for (const constraints::Body& body : problem.bodies())
      solve->body_poses.push_back(body.pose);
    for (const constraints::Variable& variable : problem.variables())
      solve->variables.push_back(variable.value);
    solve->equations = report.value().equations;
    solve->parameters = report.value().parameters;
    solve->iterations = report.value().iterations;
    solve->change = report.value().change;
  }

  ScenePlacement placement;
  placement.constraints = static_cast<int>(problem.constraints().size());
  placement.equations = solve->equations;
  placement.parameters = solve->parameters;
  placement.iterations = solve->iterations;
  placement.change = solve->change;
  for (std::size_t body = 0; body < before.size(); ++body) {
    const Pose& solved = solve->body_poses[body];
    if (solved.matrix() == before[body].pose.matrix()) continue;
    const std::size_t index = reader.objectOfBody()[body];
    SceneObject& object = scene.objects[index];
    const Pose correction = solved * before[body].pose.inverse();
    for (Pose& pose : object.poses)
      pose = correction * pose;
    object.poses[0] = solved;  // frame 0 exactly as solved, not through the product
    for (std::size_t f = 0; f < object.poses.size(); ++f) {
      if (object.poses[f].translation().cwiseAbs().maxCoeff() > kMaxCoordinate) {
        r.fail(list, "the solve moves object '" + object.name + "' in frame " + std::to_string(f) +
                         " beyond the coordinate limit");
      }
    }
    placement.moved.push_back(index);
    placement.corrections.push_back(correction);
  }
  for (std::size_t v = 0; v < problem.variables().size(); ++v)
    placement.variables.emplace_back(problem.variables()[v].name, solve->variables[v]);
  for (std::size_t k = 0; k < reader.clearances().size(); ++k) {
    const constraints::Constraint& clearance = problem.constraints()[reader.clearances()[k]];
    if (solved_here) {
      const std::size_t a = reader.objectOfBody()[clearance.p.body];
      const std::size_t b = reader.objectOfBody()[clearance.q.body];
      solve->clearances.push_back(
          exactMeshDistance(*meshes[clearance.p.body], scene.objects[a].poseAt(0),
                            *meshes[clearance.q.body], scene.objects[b].poseAt(0))
              .distance);
    }
    placement.clearances.emplace_back(clearance.name, solve->clearances[k]);
  }
  if (solved_here && !stored_path.empty()) writeStoredSolve(stored_path, *solve);
  scene.placement = std::move(placement);
}

}  // namespace collido::scene_reading
