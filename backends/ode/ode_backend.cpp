// ODE (the Open Dynamics Engine) as a Collidoscope comparator: one dTriMesh geom per model, two
// of them collided with dCollide. README.md has the measured consequences of what follows.
//
// What ODE 0.16's trimesh-trimesh collider does (collision_trimesh_trimesh.cpp, the OPCODE "new
// collider" that dGetConfiguration() names ODE_OPC_new_collider), in the order it does it:
//   1. OPCODE's AABBTreeCollider lists every triangle pair its overlap test accepts; the test is
//      Moller's, in single precision (OPCODE's points, boxes and matrices are floats);
//   2. each pair gets up to 8 contact points from clipping one triangle by the other; a pair whose
//      estimated depth is negative gets none (it is touching but not "penetrating");
//   3. contacts whose positions hash into the same 1e-4 cell (in the units of the frame the
//      geoms are placed in, whatever the model size) are merged: the deeper one replaces the
//      other, equal depths average their normals and take the triangle ids the trimerge
//      callback gives (-1 without a callback);
//   4. once the buffer is full new contacts are dropped silently; the pair loop stops early only
//      with CONTACTS_UNIMPORTANT.
// So the contacts name some intersecting triangle pairs, never all of them: the plugin answers
// boolean and contacts queries, and all-pairs queries only when asked to (pairs_from_contacts),
// as the pairs its contacts name.
#include <algorithm>
#include <atomic>
#include <climits>
#include <cstdarg>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <ode/ode.h>

#include <collido/ode/ode_backend.h>
#include <collido/plugin_export.h>

namespace collido::ode {
namespace {

constexpr const char* kVersion = "0.1.0";

std::atomic<std::uint64_t> g_messages{0};
thread_local std::uint64_t t_messages = 0;
std::atomic<const char*> g_last_message{""};

// ODE prints dMessage text to stderr by default; inside a timed query that is I/O on the clock
// (a dense coplanar query sends millions). Counting is all a study needs.
void countMessage(int /*errnum*/, const char* format, va_list /*args*/) {
  g_messages.fetch_add(1, std::memory_order_relaxed);
  ++t_messages;
  g_last_message.store(format != nullptr ? format : "", std::memory_order_relaxed);
}

// ODE's global state, set up once per process (dInitODE2 and the message handler). ODE's error
// and debug handlers are left as they are: ODE calls exit() or abort() as soon as they return,
// and leaving them by throwing would unwind through ODE with its thread caches half updated, so
// the best a plugin can do is avoid their causes (the contact cap, a geom against itself) and
// let ODE's own text explain the rest; the runner's worker process records the crash.
class OdeRuntime {
 public:
  static const OdeRuntime& instance() {
    static const OdeRuntime runtime;
    return runtime;
  }

  const Status& status() const { return status_; }

  OdeRuntime(const OdeRuntime&) = delete;
  OdeRuntime& operator=(const OdeRuntime&) = delete;

  // The handler points into this library: give the previous one back when it is unloaded. ODE
  // itself is not closed (dCloseODE): a model the host still holds at exit must stay valid.
  ~OdeRuntime() {
    if (handler_set_) dSetMessageHandler(previous_handler_);
  }

 private:
  OdeRuntime() {
    if (dInitODE2(0) == 0) {
      status_ = Status(StatusCode::kEngineFailure, "ode: dInitODE2 failed");
      return;
    }
    // dReal's size comes from ODE's headers (precision.h, steered by CMakeLists.txt from the .pc
    // file); a library of the other precision would read every array and matrix wrongly.
    const bool library_double = dCheckConfiguration("ODE_double_precision") != 0;
    const bool headers_double = sizeof(dReal) == sizeof(double);
    if (library_double != headers_double) {
      status_ = Status(StatusCode::kEngineFailure,
                       std::string("ode: the library is built with ") +
                           (library_double ? "double" : "single") +
                           " precision but the plugin with the other (ODE's configuration: " +
                           dGetConfiguration() + ")");
      return;
    }
    if (dCheckConfiguration("ODE_EXT_trimesh") == 0) {
      status_ = Status(StatusCode::kUnsupported, "ode: ODE is built without trimesh support");
      return;
    }
    previous_handler_ = dGetMessageHandler();
    dSetMessageHandler(&countMessage);
    handler_set_ = true;
  }

  Status status_;
  dMessageFunction* previous_handler_ = nullptr;
  bool handler_set_ = false;
};

// ODE keeps its trimesh collider caches in thread-local storage that must be allocated on each
// calling thread before its first trimesh collision.
Status prepareThread() {
  const Status& init = OdeRuntime::instance().status();
  if (!init.ok()) return init;
  thread_local bool allocated = false;
  if (!allocated) {
    if (dAllocateODEDataForThread(dAllocateMaskAll) == 0) {
      return {StatusCode::kEngineFailure, "ode: dAllocateODEDataForThread failed"};
    }
    allocated = true;
  }
  return {};
}

// Two contacts merged at equal depth keep the first contact's triangle ids, so every contact
// names one triangle pair that produced it (without this callback ODE writes -1).
int keepFirstTriangle(dGeomID /*mesh*/, int first, int /*second*/) {
  return first;
}

struct TriMeshDataDeleter {
  void operator()(dxTriMeshData* data) const { dGeomTriMeshDataDestroy(data); }
};
struct GeomDeleter {
  void operator()(dxGeom* geom) const { dGeomDestroy(geom); }
};

// OPCODE's tree as ODE builds it (OPCODECREATE with no-leaf nodes, not quantized): n - 1 nodes
// for n triangles, each a float AABB (centre and extents, 24 bytes) and two pointer-sized child
// links. Not reachable through ODE's API, so estimated from the node layout.
constexpr std::size_t kOpcodeNodeBytes = 6 * sizeof(float) + 2 * sizeof(void*);

class OdeModel final : public BackendModel {
 public:
  // Copies the mesh into arrays it owns (ODE keeps pointers to them, it copies nothing) and
  // builds ODE's data and geom over them.
  explicit OdeModel(const MeshView& mesh)
      : vertices_(static_cast<std::size_t>(mesh.vertices.size())),
        triangle_count_(static_cast<std::size_t>(mesh.triangles.cols())) {
    copyVertices(mesh.vertices);
    indices_.reserve(3 * std::max<std::size_t>(triangle_count_, 2));
    for (Eigen::Index i = 0; i < mesh.triangles.size(); ++i) {
      indices_.push_back(static_cast<dTriIndex>(mesh.triangles.data()[i]));
    }
    // OPCODE's no-leaf tree has n - 1 nodes, none for one triangle, and its collider then reads
    // a node that is not there (a crash, seen in AABBTreeCollider::Collide). A one-triangle mesh
    // is given its triangle twice; triangleId() maps the copy back.
    if (triangle_count_ == 1) {
      for (std::size_t k = 0; k < 3; ++k)
        indices_.push_back(indices_[k]);
    }
    data_ = buildData();
    geom_.reset(dCreateTriMesh(nullptr, data_.get(), nullptr, nullptr, nullptr));
    dGeomTriMeshSetTriMergeCallback(geom_.get(), &keepFirstTriangle);
    // Temporal coherence caches serve sphere, box and capsule queries only (trimesh-trimesh runs
    // OPCODE without it), but off they cannot carry anything from one query to the next.
    for (int geom_class : {dSphereClass, dBoxClass, dCapsuleClass}) {
      dGeomTriMeshEnableTC(geom_.get(), geom_class, 0);
    }
  }

  std::size_t memoryBytes() const override {
    return sizeof(*this) + vertices_.capacity() * sizeof(dReal) +
           indices_.capacity() * sizeof(dTriIndex) + nodeCount() * kOpcodeNodeBytes;
  }

  // New positions into the array ODE reads, then OPCODE's bottom-up refit of every box, or
  // (rebuild) a new OPCODE tree over them, swapped in under the same geom.
  UpdateCounters update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions, bool rebuild) {
    copyVertices(positions);
    UpdateCounters counters;
    counters.counted = true;
    if (rebuild) {
      std::unique_ptr<dxTriMeshData, TriMeshDataDeleter> fresh = buildData();
      dGeomTriMeshSetData(geom_.get(), fresh.get());
      data_ = std::move(fresh);
      counters.rebuilds = 1;
      counters.nodes_rebuilt = nodeCount();
    } else {
      dGeomTriMeshDataUpdate(data_.get());
      counters.nodes_refit = nodeCount();
    }
    return counters;
  }

  dGeomID geom() const { return geom_.get(); }

  // The id build() was given for an id ODE reports (-1 stays -1).
  std::int32_t triangleId(int side) const {
    return side >= static_cast<int>(triangle_count_) ? 0 : static_cast<std::int32_t>(side);
  }

 private:
  std::size_t nodeCount() const { return indices_.size() / 3 - 1; }

  // ODE's data over the arrays this model owns: OPCODE builds its tree here.
  std::unique_ptr<dxTriMeshData, TriMeshDataDeleter> buildData() {
    std::unique_ptr<dxTriMeshData, TriMeshDataDeleter> data(dGeomTriMeshDataCreate());
    const int vertex_count = static_cast<int>(vertices_.size() / 3);
    const int index_count = static_cast<int>(indices_.size());
#if defined(dDOUBLE)
    dGeomTriMeshDataBuildDouble(data.get(), vertices_.data(), 3 * sizeof(dReal), vertex_count,
                                indices_.data(), index_count, 3 * sizeof(dTriIndex));
#else
    dGeomTriMeshDataBuildSingle(data.get(), vertices_.data(), 3 * sizeof(dReal), vertex_count,
                                indices_.data(), index_count, 3 * sizeof(dTriIndex));
#endif
    return data;
  }

  template <typename Matrix>
  void copyVertices(const Matrix& positions) {
    for (Eigen::Index c = 0; c < positions.cols(); ++c) {
      for (Eigen::Index r = 0; r < 3; ++r) {
        vertices_[static_cast<std::size_t>(3 * c + r)] = static_cast<dReal>(positions(r, c));
      }
    }
  }

  std::vector<dReal> vertices_;  // x, y, z per vertex; never reallocated: ODE points into it
  std::vector<dTriIndex> indices_;
  std::size_t triangle_count_ = 0;
  std::unique_ptr<dxTriMeshData, TriMeshDataDeleter> data_;
  std::unique_ptr<dxGeom, GeomDeleter> geom_;  // declared last: destroyed before its data
};

void placeGeom(dGeomID geom, const Pose& pose) {
  const Eigen::Matrix3d& r = pose.linear();
  const Eigen::Vector3d& t = pose.translation();
  // dMatrix3 is 3 rows of 4, row-major, the fourth column unused.
  const dMatrix3 rotation = {r(0, 0), r(0, 1), r(0, 2), 0,       r(1, 0), r(1, 1),
                             r(1, 2), 0,       r(2, 0), r(2, 1), r(2, 2), 0};
  dGeomSetRotation(geom, rotation);
  dGeomSetPosition(geom, t.x(), t.y(), t.z());
}

class OdeBackend final : public Backend {
 public:
  OdeBackend(bool pairs_from_contacts, bool rebuild)
      : pairs_from_contacts_(pairs_from_contacts), rebuild_(rebuild) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kContacts;
    if (pairs_from_contacts_) caps.queries |= QueryKind::kAllPairs;
    caps.update = true;
    caps.counts_update_work = true;
    caps.max_contacts = kMaxContactsPerCall;
    caps.notes =
        "dCollide on two dTriMesh geoms (OPCODE AABB tree; triangle overlap in single "
        "precision). Contacts are ODE's reduced set: merged within a 1e-4 position hash, each "
        "naming one triangle pair that produced it; depth is per triangle pair; at most 65,535 "
        "per query (truncated when the buffer fills). ";
    caps.notes += pairs_from_contacts_
                      ? "all_pairs: only the pairs the contacts name, a subset by construction."
                      : "No all_pairs: the contacts name only some intersecting pairs "
                        "(option pairs_from_contacts=true answers with those).";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& /*needs*/,
                                              const StateSibling& /*sibling*/) override {
    if (Status s = prepareThread(); !s.ok()) return s;
    // ODE takes counts as int: 3 indices per triangle must fit.
    if (mesh.triangles.cols() > INT_MAX / 3 || mesh.vertices.cols() > INT_MAX) {
      return Status(StatusCode::kUnsupported, "ode: ODE counts indices in int; the mesh has " +
                                                  std::to_string(mesh.triangles.cols()) +
                                                  " triangles");
    }
    // Every query kind uses the same geom, and an update needs only the vertex array every
    // model owns anyway, so the needs change nothing.
    return std::unique_ptr<BackendModel>(std::make_unique<OdeModel>(mesh));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override {
    if (Status s = prepareThread(); !s.ok()) return s;
    counters = static_cast<OdeModel&>(model).update(positions, rebuild_);
    return {};
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    if (Status s = prepareThread(); !s.ok()) return s;
    if (&a == &b) {
      // dCollide returns 0 for a geom against itself whatever the poses.
      return {StatusCode::kUnsupported,
              "ode: a model cannot be queried against itself; build the mesh twice"};
    }
    const OdeModel& model_a = static_cast<const OdeModel&>(a);
    const OdeModel& model_b = static_cast<const OdeModel&>(b);
    // A at the identity and B at the relative pose: OPCODE rounds both placements to float, and
    // an identity rounds exactly, so only B's relative placement is rounded once.
    placeGeom(model_a.geom(), Pose::Identity());
    placeGeom(model_b.geom(), pose_a.inverse(Eigen::Isometry) * pose_b);

    switch (request.kind) {
      case QueryKind::kBoolean:
        return booleanQuery(model_a, model_b, result);
      case QueryKind::kAllPairs:
        return allPairsQuery(model_a, model_b, request.max_pairs, result);
      case QueryKind::kContacts:
        return contactsQuery(model_a, model_b, pose_a, request.max_contacts, result);
      default:  // not offered (ODE has no trimesh-trimesh distance): the host refuses it first
        break;
    }
    return {StatusCode::kUnsupported,
            std::string("ode: does not answer ") + queryKindName(request.kind) + " queries"};
  }

 private:
  // Runs dCollide with room for `capacity` contacts (1 .. kMaxContactsPerCall) and returns how
  // many it wrote into contacts_.
  std::size_t collide(const OdeModel& a, const OdeModel& b, std::size_t capacity,
                      bool unimportant) {
    if (contacts_.size() < capacity) contacts_.resize(capacity);
    int flags = static_cast<int>(capacity);
    if (unimportant) flags |= static_cast<int>(CONTACTS_UNIMPORTANT);
    const int n = dCollide(a.geom(), b.geom(), flags, contacts_.data(), sizeof(dContactGeom));
    return n > 0 ? static_cast<std::size_t>(n) : 0;
  }

  // Trimesh-trimesh never swaps its geoms (both are one class), but a swapped contact would
  // name B's triangle first and point the other way; read it through g1 to be safe.
  static bool swapped(const dContactGeom& c, const OdeModel& a) { return c.g1 != a.geom(); }

  // The triangles a contact names, as build() numbered them (-1 where ODE gives none).
  static TrianglePair contactPair(const dContactGeom& c, const OdeModel& a, const OdeModel& b) {
    const bool swap = swapped(c, a);
    return TrianglePair{a.triangleId(swap ? c.side2 : c.side1),
                        b.triangleId(swap ? c.side1 : c.side2)};
  }

  // One contact slot and CONTACTS_UNIMPORTANT: ODE leaves its pair loop after the first contact.
  // OPCODE still lists every overlapping pair first (ODE runs it without "first contact").
  Status booleanQuery(const OdeModel& a, const OdeModel& b, QueryResult& result) {
    const std::size_t n = collide(a, b, 1, true);
    result.intersecting = n > 0;
    if (n > 0) {
      const TrianglePair pair = contactPair(contacts_[0], a, b);
      if (pair.a >= 0 && pair.b >= 0) result.pairs.push_back(pair);
    }
    return {};
  }

  // The distinct triangle pairs named by a full contact query: a subset of the intersecting
  // pairs (README.md). Truncated when the contact buffer filled or max_pairs stopped it.
  Status allPairsQuery(const OdeModel& a, const OdeModel& b, std::uint64_t max_pairs,
                       QueryResult& result) {
    const std::size_t n = collide(a, b, kMaxContactsPerCall, false);
    result.intersecting = n > 0;
    for (std::size_t i = 0; i < n; ++i) {
      const TrianglePair pair = contactPair(contacts_[i], a, b);
      if (pair.a >= 0 && pair.b >= 0) result.pairs.push_back(pair);
    }
    std::sort(result.pairs.begin(), result.pairs.end());
    result.pairs.erase(std::unique(result.pairs.begin(), result.pairs.end()), result.pairs.end());
    result.truncated = n == kMaxContactsPerCall;
    if (max_pairs > 0 && result.pairs.size() > max_pairs) {
      result.pairs.resize(static_cast<std::size_t>(max_pairs));
      result.truncated = true;
    }
    return {};
  }

  // Below the cap one slot more than asked tells whether more contacts exist; at the cap the
  // buffer filling is all ODE says, and it is reported as truncated.
  Status contactsQuery(const OdeModel& a, const OdeModel& b, const Pose& pose_a,
                       std::uint64_t max_contacts, QueryResult& result) {
    const std::uint64_t limit = max_contacts == 0 || max_contacts > kMaxContactsPerCall
                                    ? kMaxContactsPerCall
                                    : max_contacts;
    const std::uint64_t capacity = limit < kMaxContactsPerCall ? limit + 1 : limit;
    const std::size_t n = collide(a, b, static_cast<std::size_t>(capacity), false);
    result.intersecting = n > 0;
    result.truncated = n > limit || n == kMaxContactsPerCall;
    const std::size_t kept = n > limit ? static_cast<std::size_t>(limit) : n;
    result.contacts.resize(kept);
    const Eigen::Matrix3d& rotation = pose_a.linear();
    for (std::size_t i = 0; i < kept; ++i) {
      const dContactGeom& c = contacts_[i];
      Contact& out = result.contacts[i];
      // Computed in A's frame (A was placed at the identity); ODE's normal points into g1, ours
      // from A towards B.
      const double sign = swapped(c, a) ? 1.0 : -1.0;
      out.position = pose_a * Eigen::Vector3d(c.pos[0], c.pos[1], c.pos[2]);
      out.normal = sign * (rotation * Eigen::Vector3d(c.normal[0], c.normal[1], c.normal[2]));
      out.depth = c.depth;
      const TrianglePair pair = contactPair(c, a, b);
      out.triangle_a = pair.a;
      out.triangle_b = pair.b;
    }
    return {};
  }

  bool pairs_from_contacts_;
  bool rebuild_;
  std::vector<dContactGeom> contacts_;  // kept across queries: up to 65,535 x 96 bytes
};

Result<std::unique_ptr<Backend>> create(const std::string& /*variant*/, BackendOptions& options) {
  Result<bool> pairs = options.getBool("pairs_from_contacts", false);
  if (!pairs.ok()) return pairs.status();
  // rebuild=true: update() builds a new OPCODE tree instead of dGeomTriMeshDataUpdate's refit.
  Result<bool> rebuild = options.getBool("rebuild", false);
  if (!rebuild.ok()) return rebuild.status();
  if (Status s = prepareThread(); !s.ok()) return s;
  return std::unique_ptr<Backend>(std::make_unique<OdeBackend>(pairs.value(), rebuild.value()));
}

// ODE has no version call; CMakeLists.txt passes the version of its pkg-config file.
std::string engineVersion() {
  return std::string(COLLIDO_ODE_VERSION) +
         (sizeof(dReal) == sizeof(double) ? " (double precision)" : " (single precision)");
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "ode",
      kVersion,
      "Open Dynamics Engine",
      engineVersion(),
      {{"ode",
        "ODE trimesh-trimesh dCollide (OPCODE AABB tree, merged contacts, at most 65,535); "
        "option pairs_from_contacts (default false) adds all_pairs as the pairs contacts name, "
        "rebuild (default false: update() refits OPCODE's boxes; true builds a new tree)"}},
      &create};
  return info;
}

}  // namespace

std::uint64_t odeMessagesOnThisThread() {
  return t_messages;
}

std::uint64_t odeMessagesTotal() {
  return g_messages.load(std::memory_order_relaxed);
}

const char* lastOdeMessageFormat() {
  return g_last_message.load(std::memory_order_relaxed);
}

}  // namespace collido::ode

COLLIDO_DEFINE_PLUGIN(ode, collido::ode::describe)
