// Scene hierarchy: objects mounted on parents (scene key "parent"), checked before any object is
// read, and each object's motion composed with its parent's (scenes/README.md, "Hierarchy").
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <collido/scene/scene.h>

#include "scene_reader.h"

namespace collido::scene_reading {

/// The objects' names and parents as the file gives them.
struct Hierarchy {
  std::vector<std::string> names;                   ///< per object, in file order
  std::vector<std::optional<std::size_t>> parents;  ///< per object: its parent's index
  /// The order objects are read in: file order, except that a parent comes before its children.
  std::vector<std::size_t> order;
};

/// Reads every object's "name" and "parent" in `objects` (the scene's /objects array, each entry
/// checked against `object_keys`). Errors name the JSON path: a missing, empty or duplicate name,
/// an unknown parent, an object that is its own parent, and a cycle of parents (listed).
Hierarchy readHierarchy(const Reader& r, const Node& objects,
                        const std::set<std::string>& object_keys);

/// Takes `object.poses`, given relative to `parent`, into the world: frame by frame the parent's
/// pose composed with the object's. When an ancestor is tracked, the object follows the
/// ancestors' recovered poses and keeps the true ones beside them; `tracked`: the object has
/// markers of its own, which are then generated from (or compared with) the true poses, so
/// those become object.poses. Fails at `at` when a composed translation passes the coordinate
/// limit.
void composeWithParent(const Reader& r, const Node& at, const SceneObject& parent,
                       std::size_t frames, bool tracked, SceneObject& object);

/// Takes `object.poses`, given in the world frame by frame (a random motion's placements against
/// another object), relative to `parent`'s true poses, so that composeWithParent gives them back
/// and the object stays mounted: it belongs to the parent's subtree and its children follow it.
void expressRelativeToParent(const SceneObject& parent, SceneObject& object);

}  // namespace collido::scene_reading
