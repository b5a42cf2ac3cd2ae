// Scene files: JSON in, a fully validated Scene out.
//
// The reader walks the document with its JSON pointer in hand, so every complaint names the
// file, the place and the problem. Errors are thrown as SceneError inside this file only and
// returned as a Status; unknown keys are errors (a misspelt "minor_raduis" must not silently
// become the default), except "comment", allowed anywhere for notes.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <collido/mesh/input_file.h>
#include <collido/scene/scene.h>

#include "constraint_reader.h"
#include "deformation_reader.h"
#include "frame_ranges_reader.h"
#include "hierarchy_reader.h"
#include "marker_reader.h"
#include "motion_reader.h"
#include "query_reader.h"
#include "scene_reader.h"
#include "shape_reader.h"
#include "stress_reader.h"

namespace collido {
namespace {

using scene_reading::Json;
using scene_reading::LoadedShape;
using scene_reading::Node;
using scene_reading::Reader;
using scene_reading::SceneError;
using scene_reading::ShapeLoader;

// The object's shape: one ("shape"), or active states ("states", with a "schedule").
void readShapes(const Reader& r, const Node& node, std::size_t frames, ShapeLoader& shapes,
                SceneObject& object) {
  if (!node.has("shape") && !node.has("states"))
    r.fail(node, "missing 'shape' (or 'states', a list of shapes)");
  if (node.has("shape") && node.has("states"))
    r.fail(node, "give only one of 'shape' or 'states' (a list of shapes)");
  if (node.has("shape")) {
    if (node.has("schedule")) r.fail(node.at("schedule"), "a schedule needs 'states'");
    LoadedShape shape = shapes.load(node.at("shape"));
    object.mesh = shape.mesh;
    object.report = shape.report;
  } else {
    const Node list = node.at("states");
    r.expectArray(list);
    if (list.value.empty()) r.fail(list, "an object with states needs at least one");
    for (std::size_t k = 0; k < list.value.size(); ++k) {
      LoadedShape shape = shapes.load(list.at(k));
      object.states.push_back(ObjectState{shape.mesh, shape.report});
    }
    object.mesh = object.states.front().mesh;
    object.report = object.states.front().report;
    const Node schedule = node.has("schedule") ? node.at("schedule") : list;
    object.schedule = scene_reading::readSchedule(r, node.has("schedule") ? &schedule : nullptr,
                                                  object.states.size(), frames);
  }
}

// The object's movable nodes ("deform"), read once its shapes and poses are: a drape casts from
// its first pose onto an earlier object. Every deformed frame is computed once here, so a scene
// that loads holds finite shapes within the coordinate limit in every frame.
void readDeform(const Reader& r, const Node& node, const std::string& base_directory,
                const Scene& scene, const std::map<std::string, std::size_t>& index_of,
                SceneObject& object) {
  if (!node.has("deform")) return;
  const Node deform = node.at("deform");
  scene_reading::DeformContext context;
  context.object = &object;
  context.earlier = [&](const std::string& name) -> const SceneObject* {
    const auto found = index_of.find(name);
    return found == index_of.end() ? nullptr : &scene.objects[found->second];
  };
  object.deformation =
      scene_reading::readDeformation(r, deform, base_directory, scene.frames, context);
  for (std::size_t state = 0; state < object.stateCount(); ++state) {
    const std::size_t vertices = object.stateMesh(state)->vertexCount();
    if (object.deformation->recorded && object.deformation->recorded->vertices != vertices) {
      r.fail(deform.at("recorded"), "records " +
                                        std::to_string(object.deformation->recorded->vertices) +
                                        " vertices but state " + std::to_string(state) + " has " +
                                        std::to_string(vertices));
    }
  }
  for (std::size_t f = 0; f < scene.frames; ++f) {
    const std::shared_ptr<const TriangleMesh> shape = object.shapeAt(f);
    const double largest = shape->vertices.cwiseAbs().maxCoeff();
    if (!std::isfinite(largest) || largest > kMaxCoordinate) {
      std::ostringstream text;
      text << "frame " << f << ": the deformation takes a vertex to " << largest
           << ", beyond the coordinate limit " << kMaxCoordinate << " (scenes/README.md)";
      r.fail(deform, text.str());
    }
  }
}

/// A drape casts its stop distances against both objects' frame-0 poses when it is read: a
/// constraint solve may then move neither (the sheet would float or cut in).
void markDrapes(const Node& node, const std::map<std::string, std::size_t>& index_of,
                std::vector<scene_reading::ObjectMotionSource>& sources, std::size_t object) {
  if (!node.has("deform") || !node.value["deform"].is_object()) return;
  const Json& rules = node.value["deform"].value("rules", Json::array());
  for (const Json& rule : rules) {
    if (!rule.is_object() || !rule.contains("drape")) continue;
    sources[object].draped = true;
    const Json& onto = rule["drape"].value("onto", Json());
    if (!onto.is_string()) continue;
    const auto found = index_of.find(onto.get<std::string>());
    if (found != index_of.end()) sources[found->second].drape_target = true;
  }
}

Scene readScene(const Reader& r, const Json& document, const std::string& base_directory,
                const SceneLoadOptions& options) {
  const Node root{document, ""};
  r.expectObject(
      root, {"name", "description", "up", "frames", "objects", "constraints", "queries", "stress"});
  Scene scene;
  scene.name = root.has("name") ? r.string(root.at("name")) : "";
  scene.description = root.has("description") ? r.string(root.at("description")) : "";
  if (root.has("up")) {
    const Eigen::Vector3d up = r.vector3(root.at("up"));
    if (!(up.norm() > 0.0) || !std::isfinite(up.norm()))
      r.fail(root.at("up"), "must be a non-zero direction");
    scene.up = up.normalized();
  }
  if (root.has("stress")) {
    scene_reading::readStress(r, root, base_directory, options, scene);
    return scene;
  }
  const bool frames_given = root.has("frames");
  const auto max_frames = static_cast<std::int64_t>(
      std::min<std::size_t>(options.max_frames, std::numeric_limits<std::int64_t>::max()));
  if (frames_given)
    scene.frames = static_cast<std::size_t>(r.integer(root.at("frames"), 1, max_frames));

  if (!root.has("objects")) r.fail(root, "missing 'objects'");
  const Node objects = root.at("objects");
  r.expectArray(objects);
  if (objects.value.empty()) r.fail(objects, "a scene needs at least one object");

  // Frame count from explicit pose lists when the scene does not state it.
  if (!frames_given) {
    for (std::size_t i = 0; i < objects.value.size(); ++i) {
      const Json& o = objects.value[i];
      if (o.is_object() && o.contains("motion") && o["motion"].is_object() &&
          o["motion"].contains("poses") && o["motion"]["poses"].is_array()) {
        const std::size_t count = o["motion"]["poses"].size();
        if (count > options.max_frames) {
          r.fail(objects.at(i).at("motion").at("poses"),
                 "has " + std::to_string(count) + " poses, more frames than this load allows (" +
                     std::to_string(options.max_frames) + ", SceneLoadOptions::max_frames)");
        }
        scene.frames = std::max<std::size_t>(scene.frames, count);
      }
    }
  }

  ShapeLoader shapes(r, base_directory, options.max_triangles);
  const scene_reading::Hierarchy hierarchy =
      scene_reading::readHierarchy(r, objects,
                                   {"name", "parent", "shape", "states", "schedule", "deform",
                                    "pose", "motion", "markers", "frames"});
  // Objects are read parents first (a child's poses compose with its parent's) but keep their
  // file order in the scene; `index_of` holds the objects read so far.
  std::map<std::string, std::size_t> index_of;
  std::vector<scene_reading::ObjectMotionSource> sources(objects.value.size());
  scene.objects.resize(objects.value.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i)
    scene.objects[i].name = hierarchy.names[i];
  for (const std::size_t i : hierarchy.order) {
    const Node node = objects.at(i);
    SceneObject& object = scene.objects[i];
    readShapes(r, node, scene.frames, shapes, object);
    scene_reading::readMotion(r, node, scene, index_of, sources, i, object);
    sources[i].tracked = node.has("markers");
    if (const std::optional<std::size_t> parent = hierarchy.parents[i]) {
      object.parent = parent;
      sources[i].has_parent = true;
      sources[*parent].has_children = true;
      // A random motion places the object in the world, against another object.
      if (sources[i].kind == "random") {
        scene_reading::expressRelativeToParent(scene.objects[*parent], object);
      }
      scene_reading::composeWithParent(r, node.at("parent"), scene.objects[*parent], scene.frames,
                                       sources[i].tracked, object);
      const SceneObject& mount = scene.objects[*parent];
      if (!sources[i].tracked)
        object.tracked_ancestor = mount.tracking ? parent : mount.tracked_ancestor;
    }
    if (node.has("markers"))
      scene_reading::readMarkers(r, node.at("markers"), base_directory, scene.frames, object);
    readDeform(r, node, base_directory, scene, index_of, object);
    if (node.has("frames"))
      object.present = scene_reading::readFrameRanges(r, node.at("frames"), scene.frames);
    markDrapes(node, index_of, sources, i);
    index_of.emplace(object.name, i);
  }

  if (root.has("constraints")) {
    scene_reading::solveSceneConstraints(r, root.at("constraints"), sources,
                                         options.placement_store, scene);
  }

  if (!root.has("queries")) r.fail(root, "missing 'queries'");
  scene_reading::readQueries(r, root.at("queries"), index_of, scene);
  return scene;
}

}  // namespace

bool SceneQuery::asksPair(std::size_t i, std::size_t j) const {
  if (!isGroup()) return (i == a && j == b) || (i == b && j == a);
  if (i == j || !names(i) || !names(j)) return false;
  const std::pair<std::size_t, std::size_t> pair = std::minmax(i, j);
  if (std::binary_search(except.begin(), except.end(), pair)) return false;
  return side_b.empty() || std::binary_search(side_b.begin(), side_b.end(), i) !=
                               std::binary_search(side_b.begin(), side_b.end(), j);
}

std::vector<std::size_t> Scene::subtree(std::size_t root) const {
  // Parents may come after their children in the file: follow each object up to a root.
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::optional<std::size_t> at = i; at; at = objects[*at].parent) {
      if (*at == root) {
        out.push_back(i);
        break;
      }
    }
  }
  return out;
}

bool SceneQuery::names(std::size_t object) const {
  if (isGroup()) return std::binary_search(among.begin(), among.end(), object);
  return object == a || object == b;
}

std::vector<std::size_t> SceneQuery::objects() const {
  if (isGroup()) return among;
  return {a, b};
}

BuildNeeds Scene::needsOf(std::size_t object) const {
  BuildNeeds needs;
  for (const SceneQuery& q : queries) {
    if (q.names(object)) needs.queries |= q.request.kind;
  }
  needs.deforms = objects[object].deformation != nullptr;
  // The objects linked to this one through queries, directly or through others: grown until no
  // query adds one, so every object of a linked set gets the same kinds.
  std::vector<bool> linked(objects.size(), false);
  linked[object] = true;
  for (bool grew = true; grew;) {
    grew = false;
    for (const SceneQuery& q : queries) {
      const std::vector<std::size_t> named = q.objects();
      if (std::none_of(named.begin(), named.end(), [&](std::size_t i) { return linked[i]; })) {
        continue;
      }
      needs.linked_queries |= q.request.kind;
      for (std::size_t i : named) {
        grew = grew || !linked[i];
        linked[i] = true;
      }
    }
  }
  return needs;
}

std::vector<std::size_t> Scene::queriedObjects() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!needsOf(i).queries.empty()) out.push_back(i);
  }
  return out;
}

Result<Scene> parseScene(const std::string& text, const std::string& label,
                         const std::string& base_directory, const SceneLoadOptions& options) {
  if (!(options.resolution > 0.0) || !std::isfinite(options.resolution)) {
    return Status(StatusCode::kInvalidArgument,
                  label + ": resolution must be a positive finite number");
  }
  Result<Json> parsed = scene_reading::parseDocument(text, label);
  if (!parsed.ok()) return parsed.status();
  const Json& document = parsed.value();
  try {
    const Reader reader(label, options.resolution);
    Scene scene = readScene(reader, document, base_directory, options);
    scene.resolution = options.resolution;
    if (scene.name.empty()) scene.name = std::filesystem::path(label).stem().string();
    return scene;
  } catch (const SceneError& e) {
    return Status(StatusCode::kInvalidArgument, e.what());
  } catch (const Json::exception& e) {
    return Status(StatusCode::kInvalidArgument, label + ": " + e.what());
  }
}

bool Scene::hasTrackedObjects() const {
  return std::any_of(objects.begin(), objects.end(),
                     [](const SceneObject& o) { return o.tracking != nullptr; });
}

Scene Scene::withTruePoses() const {
  Scene truth = *this;
  for (SceneObject& object : truth.objects) {
    if (object.tracking) {
      object.poses = object.tracking->true_poses;
      object.tracking.reset();
    } else if (!object.inherited_true_poses.empty()) {
      object.poses = std::move(object.inherited_true_poses);
      object.inherited_true_poses.clear();
    }
    object.tracked_ancestor.reset();
  }
  return truth;
}

bool Scene::hasGeneratedShapes() const {
  return std::any_of(objects.begin(), objects.end(), [](const SceneObject& o) {
    return o.report.importer == "generator" ||
           std::any_of(o.states.begin(), o.states.end(), [](const ObjectState& state) {
             return state.report.importer == "generator";
           });
  });
}

Result<Scene> loadScene(const std::string& path, const SceneLoadOptions& options) {
  const InputFileRecorder inputs;
  Result<std::string> text = readInputFile(path, "scene file");
  if (!text.ok()) return text.status();
  Result<Scene> scene =
      parseScene(text.value(), path, std::filesystem::path(path).parent_path().string(), options);
  if (scene.ok()) {
    scene.value().path = path;
    scene.value().input_files = inputs.files();
  }
  return scene;
}

}  // namespace collido
