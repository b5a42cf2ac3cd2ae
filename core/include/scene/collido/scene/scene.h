#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <collido/capabilities.h>
#include <collido/geometry.h>
#include <collido/mesh/mesh_report.h>
#include <collido/mesh/triangle_mesh.h>
#include <collido/query.h>
#include <collido/scene/deformation.h>
#include <collido/scene/marker_tracking.h>
#include <collido/status.h>

namespace collido {

/// The frames an object exists in, or a query is asked in: inclusive [first, last] ranges,
/// ascending and apart (scene key "frames"). Empty: every frame.
struct FrameRanges {
  std::vector<std::pair<std::size_t, std::size_t>> ranges;

  bool everyFrame() const { return ranges.empty(); }
  bool contains(std::size_t frame) const;
  /// How many of the first `frames` frames it holds.
  std::size_t countIn(std::size_t frames) const;
  /// "every frame", or "frames 0-9, 20, 22-24".
  std::string text() const;
};

/// One precomputed shape of an object with active states.
struct ObjectState {
  std::shared_ptr<const TriangleMesh> mesh;
  MeshReport report;
};

/// One object of a scene: a shape and its pose in every frame. A deformable object also has
/// active states (a few precomputed shapes, one active per frame) and movable nodes (a
/// Deformation of the active state's vertices, frame by frame), or both.
struct SceneObject {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;  ///< the rest shape (state 0); shared between
                                             ///< objects using the same source
  MeshReport report;                         ///< where the mesh came from and what is in it
  std::vector<Pose> poses;                   ///< one per frame, or one for every frame
  /// Active states: empty, or every state in order (states[0].mesh == mesh).
  std::vector<ObjectState> states;
  /// The active state per frame (indices into states); empty: state 0 throughout.
  std::vector<std::size_t> schedule;
  /// Movable nodes, applied to the active state's vertices; empty for none.
  std::shared_ptr<const Deformation> deformation;
  /// Tracked markers: `poses` are then the poses recovered from them, and the tracking holds
  /// the true ones. Null for an object whose poses are given.
  std::shared_ptr<const MarkerTracking> tracking;
  /// The object it is mounted on (scene key "parent"), an index into Scene::objects; empty for
  /// a root. `poses` are world poses all the same: the parent's composed with the object's own
  /// motion relative to it, so a child follows its parent (scenes/README.md, "Hierarchy").
  std::optional<std::size_t> parent;
  /// Set when an ancestor is tracked and this object is not: the world poses the true motions
  /// give (`poses` follow the ancestors' recovered poses, as a tracker's world would).
  std::vector<Pose> inherited_true_poses;
  /// Set when an ancestor is tracked and this object is not: the nearest tracked ancestor,
  /// whose fitting noise moves this object with it (Scene::trackingSpreadAt).
  std::optional<std::size_t> tracked_ancestor;
  /// The frames it exists in (an application's object added or removed mid-run); its poses
  /// outside them are placeholders that no query reads.
  FrameRanges present;

  /// The object's world pose in `frame`: what every query uses (recovered, when tracked).
  const Pose& poseAt(std::size_t frame) const {
    return poses.size() == 1 ? poses[0] : poses[frame];
  }
  /// The pose the scene's motion gives in `frame`: poseAt() unless the object is tracked.
  const Pose& truePoseAt(std::size_t frame) const {
    if (tracking) return tracking->true_poses[frame];
    if (!inherited_true_poses.empty()) {
      return inherited_true_poses.size() == 1 ? inherited_true_poses[0]
                                              : inherited_true_poses[frame];
    }
    return poseAt(frame);
  }
  /// Whether its shape changes between frames (states or movable nodes).
  bool changesShape() const { return deformation != nullptr || states.size() > 1; }
  std::size_t stateCount() const { return states.empty() ? 1 : states.size(); }
  /// The state active in `frame`.
  std::size_t stateAt(std::size_t frame) const { return schedule.empty() ? 0 : schedule[frame]; }
  /// The rest shape of state `state`.
  const std::shared_ptr<const TriangleMesh>& stateMesh(std::size_t state) const {
    return states.empty() ? mesh : states[state].mesh;
  }
  /// The shape in `frame` (in the object's own frame): the active state's mesh, its vertices
  /// moved by the deformation. The rest mesh itself when the object does not deform.
  std::shared_ptr<const TriangleMesh> shapeAt(std::size_t frame) const;
};

/// The bracket width of a query asked over a step whose file gives none: a thousandth of the
/// step.
inline constexpr double kDefaultBracketWidth = 1e-3;

/// One question asked in every frame (or those of `asked`): of two objects, or of a group of
/// objects after a shared broad phase (a pile: every object pair whose bounds may touch gets the
/// question).
struct SceneQuery {
  std::string name;   ///< unique in the scene
  std::size_t a = 0;  ///< index into Scene::objects (a two-object query)
  std::size_t b = 0;  ///< index into Scene::objects (a two-object query)
  /// Non-empty: a group query over these objects (at least two, ascending); `a` and `b` are
  /// then unused. Only all-pairs questions are asked of groups.
  std::vector<std::size_t> among;
  /// Non-empty only for a group query of one set against another (subtree against subtree):
  /// the second set (ascending, within `among`); only pairs with one object in it and the other
  /// not are asked. Empty: every pair of `among` is.
  std::vector<std::size_t> side_b;
  /// A group query's object pairs not asked (the file's "except": a robot's allowed-collision
  /// pairs), each (low, high) index, sorted.
  std::vector<std::pair<std::size_t, std::size_t>> except;
  QueryRequest request;
  /// The frames it is asked in; a group query skips a pair whose object is absent. A query
  /// over a step (QueryKindInfo::over_a_step) asked in frame k asks about the step to k + 1.
  FrameRanges asked;

  bool isGroup() const { return !among.empty(); }
  /// Whether the query asks anything of `object`.
  bool names(std::size_t object) const;
  /// Whether the query asks about the object pair (i, j), i != j: both named, not an `except`
  /// pair and, for a query of two sets, on different sides.
  bool asksPair(std::size_t i, std::size_t j) const;
  /// The objects it asks about: `among`, or {a, b}.
  std::vector<std::size_t> objects() const;
};

/// What a scene's `constraints` block did at load (scenes/README.md, "Constraints"): the
/// least-change solve's figures and what it moved.
struct ScenePlacement {
  /// Objects the solve moved, and the world correction each got: every frame's pose P became
  /// correction · P (the whole motion moved rigidly so that frame 0 meets the constraints).
  std::vector<std::size_t> moved;
  std::vector<Pose> corrections;
  /// Every variable of the block with its value after the solve.
  std::vector<std::pair<std::string, double>> variables;
  /// Every clearance constraint with the exact oracle's distance after the solve.
  std::vector<std::pair<std::string, double>> clearances;
  int constraints = 0;
  int equations = 0;
  int parameters = 0;
  int iterations = 0;
  double change = 0.0;  ///< the normalised change the solve minimised
};

/// A loaded, fully validated scene: nothing in it can fail later for a reason the file holds.
struct Scene {
  std::string path;  ///< the file it was read from ("" for scenes built in code)
  /// Every file it was read from, the scene file first, then its meshes, recordings and tracks
  /// (InputFileRecorder); what a study fingerprints to notice a changed input.
  std::vector<std::string> input_files;
  std::string name;
  std::string description;
  std::size_t frames = 1;
  /// The direction the 3D view keeps up (the file's "up", a unit vector): +y by default, +z for
  /// robots from URDF (ROS's convention). Nothing but the view reads it.
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  std::vector<SceneObject> objects;
  std::vector<SceneQuery> queries;
  double resolution = 1.0;  ///< the SceneLoadOptions::resolution it was loaded with
  /// The robustness category of a stress scene (a name from collido/stress/stress_cases.h, e.g.
  /// "near_touching"), by which the study's robustness matrix groups answers; empty for ordinary
  /// scenes.
  std::string category;
  /// Set when the scene has a `constraints` block: what solving it at load did.
  std::optional<ScenePlacement> placement;

  /// Whether some object comes from a generator (whose resolution a load option can change).
  bool hasGeneratedShapes() const;
  /// Whether some object's poses are recovered from tracked markers.
  bool hasTrackedObjects() const;
  /// The scene as the world is: every tracked object at its true poses (a copy).
  Scene withTruePoses() const;
  /// How far tracking noise may move object `object` with shape `shape` (its shape in `frame`)
  /// in `frame`: the largest predicted spread over the shape's bounding-box corners, from its
  /// own markers' fit or its nearest tracked ancestor's; 0 for an object no tracking moves,
  /// NaN when the fit's spread is unknown (no redundant marker, or a lost frame).
  double trackingSpreadAt(std::size_t object, const TriangleMesh& shape, std::size_t frame) const;

  /// What the scene will ask of an object: the kinds of every query naming it.
  BuildNeeds needsOf(std::size_t object) const;
  /// Indices of the objects that some query names, in order.
  std::vector<std::size_t> queriedObjects() const;
  /// `root` and every object mounted on it, directly or further down, ascending.
  std::vector<std::size_t> subtree(std::size_t root) const;
};

/// How a scene is loaded.
struct SceneLoadOptions {
  /// Scales every generator's sample counts (segments, slices, cells, flank samples) by this
  /// factor, down to each generator's minimum: 0.5 meshes each curve with half the samples.
  /// Mesh files are read as they are.
  double resolution = 1.0;
  /// The most triangles the scene's objects may hold together (each object counted, also when
  /// objects share a mesh file); a shape that would take the scene past it is refused with an
  /// error naming its JSON path. Generated shapes are counted from their parameters before they
  /// are generated, so nothing large is allocated. 0: no scene-wide limit (each generator still
  /// refuses more than 50 million triangles a shape).
  std::size_t max_triangles = 0;
  /// The most frames the scene may have ("frames", or without it the longest "poses" list):
  /// every moving object stores one pose per frame.
  std::size_t max_frames = 1000000;
  /// A folder where solved constraint blocks are kept ("": none): a scene whose block was solved
  /// before on the same bodies takes the stored solve instead of solving again (the solve asks
  /// the exact distance oracle many times). Studies keep one beside their oracle store, so each
  /// worker does not solve the same placement again.
  std::string placement_store = {};
};

/// Reads and validates a scene file (format: scenes/README.md). Every error names the file, the
/// JSON path (e.g. /objects/2/shape/minor_radius) and the problem; meshes are loaded and
/// generated here, so a scene that loads is a scene that runs.
Result<Scene> loadScene(const std::string& path, const SceneLoadOptions& options = {});

/// As loadScene, from text; `label` names it in messages, `base_directory` resolves mesh paths.
Result<Scene> parseScene(const std::string& text, const std::string& label,
                         const std::string& base_directory, const SceneLoadOptions& options = {});

}  // namespace collido
