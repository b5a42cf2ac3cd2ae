#include "hierarchy_reader.h"

#include <algorithm>
#include <map>
#include <sstream>

#include <collido/mesh/triangle_mesh.h>

namespace collido::scene_reading {
namespace {

// Appends `object` to `order` after its ancestors (those not yet placed), so every parent is
// read before its children. The chains are known to be free of cycles.
void placeAfterAncestors(const Hierarchy& h, std::size_t object, std::vector<bool>& placed,
                         std::vector<std::size_t>& order) {
  std::vector<std::size_t> chain;
  for (std::optional<std::size_t> at = object; at && !placed[*at]; at = h.parents[*at])
    chain.push_back(*at);
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    placed[*it] = true;
    order.push_back(*it);
  }
}

}  // namespace

Hierarchy readHierarchy(const Reader& r, const Node& objects,
                        const std::set<std::string>& object_keys) {
  const std::size_t count = objects.value.size();
  Hierarchy h;
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < count; ++i) {
    const Node node = objects.at(i);
    r.expectObject(node, object_keys);
    if (!node.has("name")) r.fail(node, "missing 'name'");
    std::string name = r.string(node.at("name"));
    if (name.empty()) r.fail(node.at("name"), "the name must not be empty");
    if (!index_of.emplace(name, i).second) {
      r.fail(node.at("name"), "duplicate object name '" + name + "'");
    }
    h.names.push_back(std::move(name));
  }
  h.parents.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Node node = objects.at(i);
    if (!node.has("parent")) continue;
    const std::string parent = r.string(node.at("parent"));
    const auto found = index_of.find(parent);
    if (found == index_of.end()) r.fail(node.at("parent"), "no object named '" + parent + "'");
    if (found->second == i) r.fail(node.at("parent"), "an object cannot be its own parent");
    h.parents[i] = found->second;
  }
  // Each object is walked up once: a walk stops at a root or at an object already known to
  // lead to one, so the check is linear in the objects. Meeting the walk's own path is a
  // cycle, reported at the first of its objects in file order, listing it.
  enum class Mark { kUnseen, kOnPath, kLeadsToRoot };
  std::vector<Mark> marks(count, Mark::kUnseen);
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<std::size_t> path;
    std::optional<std::size_t> at = i;
    while (at && marks[*at] != Mark::kLeadsToRoot) {
      if (marks[*at] == Mark::kOnPath) {
        const auto seen = std::find(path.begin(), path.end(), *at);
        const std::size_t first = *std::min_element(seen, path.end());
        std::ostringstream text;
        text << "the parents form a cycle: ";
        std::size_t step = first;
        do {
          text << "'" << h.names[step] << "' -> ";
          step = *h.parents[step];
        } while (step != first);
        text << "'" << h.names[first] << "'";
        r.fail(objects.at(first).at("parent"), text.str());
      }
      marks[*at] = Mark::kOnPath;
      path.push_back(*at);
      at = h.parents[*at];
    }
    for (const std::size_t object : path)
      marks[object] = Mark::kLeadsToRoot;
  }
  std::vector<bool> placed(count, false);
  for (std::size_t i = 0; i < count; ++i)
    placeAfterAncestors(h, i, placed, h.order);
  return h;
}

void composeWithParent(const Reader& r, const Node& at, const SceneObject& parent,
                       std::size_t frames, bool tracked, SceneObject& object) {
  const bool parent_truth_differs =
      parent.tracking != nullptr || !parent.inherited_true_poses.empty();
  const bool all_frames =
      object.poses.size() > 1 || parent.poses.size() > 1 || parent.inherited_true_poses.size() > 1;
  const std::size_t count = all_frames ? frames : 1;
  const auto local = [&](std::size_t f) -> const Pose& {
    return object.poses.size() == 1 ? object.poses[0] : object.poses[f];
  };
  std::vector<Pose> world(count);
  std::vector<Pose> truth;
  for (std::size_t f = 0; f < count; ++f) {
    world[f] = parent.poseAt(f) * local(f);
    if (parent_truth_differs) truth.push_back(parent.truePoseAt(f) * local(f));
  }
  for (const std::vector<Pose>* poses : {&world, &truth}) {
    for (std::size_t f = 0; f < poses->size(); ++f) {
      const Eigen::Vector3d t = (*poses)[f].translation();
      if (!(t.cwiseAbs().maxCoeff() <= kMaxCoordinate)) {
        std::ostringstream text;
        text << "frame " << f << ": composed with its parent '" << parent.name
             << "', the translation (" << t.x() << ", " << t.y() << ", " << t.z()
             << ") is beyond the coordinate limit |t| <= " << kMaxCoordinate
             << " (scenes/README.md)";
        r.fail(at, text.str());
      }
    }
  }
  if (tracked && parent_truth_differs) {
    object.poses = std::move(truth);  // its markers follow the true motion
  } else {
    object.poses = std::move(world);
    object.inherited_true_poses = std::move(truth);
  }
}

void expressRelativeToParent(const SceneObject& parent, SceneObject& object) {
  for (std::size_t f = 0; f < object.poses.size(); ++f)
    object.poses[f] = parent.truePoseAt(f).inverse() * object.poses[f];
}

}  // namespace collido::scene_reading
