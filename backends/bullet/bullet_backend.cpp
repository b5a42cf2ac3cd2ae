// Bullet's GImpact as a Collidoscope comparator plugin. One source, compiled twice
// (backends/bullet/CMakeLists.txt): against Debian's single-precision Bullet (variant "bullet")
// and against its float64 build with BT_USE_DOUBLE_PRECISION (variant "bullet:double").
//
// What runs, per query (README.md explains each choice and measures its consequences):
//   1. B's pose relative to A is computed in double and A is put at the identity (option
//      relative_pose, default on), or both world poses are handed over as they are.
//   2. One btGImpactCollisionAlgorithm, made once per backend instance, runs processCollision on
//      the two btGImpactMeshShape models: GImpact's quantized AABB trees give the leaf pairs, and
//      btPrimitiveTriangle::find_triangle_collision_clip_method tests each triangle pair.
//   3. GImpact reports each contact point through btManifoldResult::addContactPoint, after
//      setShapeIdentifiersA/B with the part and the triangle index; the collector here overrides
//      addContactPoint to keep every point (what btCollisionWorld::contactPairTest's
//      btBridgedManifoldResult does), or, with option manifold=true, lets Bullet's persistent
//      manifold keep its at most four points as a dynamics world would.
//   4. A triangle pair with several contact points is reported once.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/Gimpact/btGImpactCollisionAlgorithm.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <LinearMath/btScalar.h>
#include <LinearMath/btTransform.h>

#include <collido/plugin_export.h>

#if !defined(COLLIDO_BULLET_PLUGIN_ID) || !defined(COLLIDO_BULLET_VARIANT)
#error "backends/bullet/CMakeLists.txt defines the plugin id and variant of each build"
#endif

namespace collido::bullet {
namespace {

constexpr const char* kVersion = "0.1.0";

// GImpact's quantized tree maps every box onto a 16-bit grid spanning the mesh's boxes grown by
// this absolute amount (btQuantizedBvhTree::calc_quantization's default boundMargin), clamping
// whatever lies outside. A refit is therefore correct only while the mesh stays in that span.
constexpr btScalar kQuantizationMargin = btScalar(1.0);

// One node of GImpact's tree; build_tree() allocates 2n of them for n triangles (2n - 1 used).
constexpr std::size_t kNodeBytes = sizeof(BT_QUANTIZED_BVH_NODE);

struct Settings {
  bool engine_margin = false;  ///< keep the margins a new btGImpactMeshShape comes with
  double margin = 0.0;         ///< else every mesh part gets this margin
  bool relative_pose = true;   ///< query in A's frame (B's relative pose computed in double)
  bool manifold = false;       ///< let a persistent manifold reduce the contacts (<= 4)
};

btTransform toBullet(const Pose& pose) {
  const Eigen::Matrix3d r = pose.linear();
  const Eigen::Vector3d t = pose.translation();
  const auto s = [](double v) { return static_cast<btScalar>(v); };
  return btTransform(btMatrix3x3(s(r(0, 0)), s(r(0, 1)), s(r(0, 2)), s(r(1, 0)), s(r(1, 1)),
                                 s(r(1, 2)), s(r(2, 0)), s(r(2, 1)), s(r(2, 2))),
                     btVector3(s(t.x()), s(t.y()), s(t.z())));
}

Eigen::Vector3d toEigen(const btVector3& v) {
  return Eigen::Vector3d(static_cast<double>(v.x()), static_cast<double>(v.y()),
                         static_cast<double>(v.z()));
}

// A mesh as GImpact sees it. Bullet keeps pointers into the vertex and index arrays (the
// btTriangleIndexVertexArray copies nothing), so the model owns them for the shape's lifetime,
// and GImpact reads the triangles from them at query time: update() writes new positions here.
class BulletModel final : public BackendModel {
 public:
  BulletModel(const MeshView& mesh, const Settings& settings)
      : settings_(settings),
        vertices_(static_cast<std::size_t>(mesh.vertices.size())),
        indices_(mesh.triangles.data(), mesh.triangles.data() + mesh.triangles.size()) {
    copyPositions(mesh.vertices);
    btIndexedMesh part;
    part.m_numTriangles = static_cast<int>(mesh.triangles.cols());
    part.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(indices_.data());
    part.m_triangleIndexStride = 3 * static_cast<int>(sizeof(int));
    part.m_numVertices = static_cast<int>(mesh.vertices.cols());
    part.m_vertexBase = reinterpret_cast<const unsigned char*>(vertices_.data());
    part.m_vertexStride = 3 * static_cast<int>(sizeof(btScalar));
    part.m_vertexType = sizeof(btScalar) == sizeof(double) ? PHY_DOUBLE : PHY_FLOAT;
    arrays_.addIndexedMesh(part, PHY_INTEGER);
    buildShape();
  }

  std::size_t memoryBytes() const override {
    // What build() leaves allocated: the arrays kept for Bullet, the mesh interface's one
    // btIndexedMesh, the shape with its array of part pointers (one entry), its one part, and the
    // part's node array as build_tree() allocates it (2n nodes of 16 bytes for n triangles).
    // btAlignedAlloc's padding (under 24 bytes for each of these six blocks) is left out.
    const std::size_t triangles = indices_.size() / 3;
    const std::size_t arrays =
        vertices_.capacity() * sizeof(btScalar) + indices_.capacity() * sizeof(int);
    const std::size_t shape = sizeof(btIndexedMesh) + sizeof(btGImpactMeshShape) +
                              sizeof(std::uintptr_t) + sizeof(btGImpactMeshShapePart);
    return sizeof(*this) + arrays + shape + 2 * triangles * kNodeBytes;
  }

  btGImpactMeshShape* shape() { return shape_.get(); }

  /// New positions, then GImpact's refit (postUpdate + updateBound re-bounds every node bottom-up
  /// over the moved triangles). When the mesh has left the span the tree was quantized over, a
  /// refit would clamp its boxes and miss contacts, so the shape is rebuilt instead.
  UpdateCounters update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) {
    copyPositions(positions);
    UpdateCounters counters;
    counters.counted = true;
    if (!insideQuantizedSpan()) {
      buildShape();
      counters.rebuilds = 1;
      counters.nodes_rebuilt = nodeCount();
      return counters;
    }
    shape_->postUpdate();
    shape_->updateBound();
    counters.nodes_refit = nodeCount();
    return counters;
  }

 private:
  template <typename Positions>
  void copyPositions(const Positions& positions) {
    for (Eigen::Index v = 0; v < positions.cols(); ++v) {
      for (int k = 0; k < 3; ++k) {
        vertices_[static_cast<std::size_t>(3 * v + k)] = static_cast<btScalar>(positions(k, v));
      }
    }
  }

  // Bounds of the vertices the triangles use, as GImpact's primitive boxes see them.
  void usedBounds(btVector3& low, btVector3& high) const {
    low.setValue(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT);
    high = -low;
    for (const int index : indices_) {
      const btScalar* p = &vertices_[3 * static_cast<std::size_t>(index)];
      const btVector3 v(p[0], p[1], p[2]);
      low.setMin(v);
      high.setMax(v);
    }
  }

  void buildShape() {
    shape_ = std::make_unique<btGImpactMeshShape>(&arrays_);
    // A new btGImpactMeshShape reports margin 0 (btConcaveShape's) while each of its parts keeps
    // the primitive manager's own default; setMargin() is the one call that reaches both.
    if (!settings_.engine_margin) shape_->setMargin(static_cast<btScalar>(settings_.margin));
    shape_->updateBound();
    const btScalar part_margin = shape_->getMeshPart(0)->getMargin();
    usedBounds(span_low_, span_high_);
    const btScalar grow = part_margin + kQuantizationMargin;
    span_low_ -= btVector3(grow, grow, grow);
    span_high_ += btVector3(grow, grow, grow);
  }

  // GImpact's refit and rebuild both cover the whole box tree of the one mesh part.
  std::uint64_t nodeCount() const {
    return static_cast<std::uint64_t>(shape_->getMeshPart(0)->getBoxSet()->getNodeCount());
  }

  bool insideQuantizedSpan() const {
    btVector3 low;
    btVector3 high;
    usedBounds(low, high);
    const btScalar m = shape_->getMeshPart(0)->getMargin();
    for (int k = 0; k < 3; ++k) {
      if (low[k] - m < span_low_[k] || high[k] + m > span_high_[k]) return false;
    }
    return true;
  }

  Settings settings_;
  std::vector<btScalar> vertices_;  // x y z per vertex, in the engine's precision
  std::vector<int> indices_;        // three per triangle, as given to build()
  btTriangleIndexVertexArray arrays_;
  std::unique_ptr<btGImpactMeshShape> shape_;
  btVector3 span_low_;  // the span GImpact quantized the tree over
  btVector3 span_high_;
};

// A contact point as GImpact reports it, in the frame the query ran in.
struct RawContact {
  btVector3 point;        // on B or on A, depending on which triangle's plane GImpact chose
  btVector3 normal_on_b;  // Bullet's convention: from B towards A
  btScalar distance;      // <= 0 with the margins counted in
  int triangle_a;
  int triangle_b;
};

// Receives GImpact's contact points. GImpact calls setShapeIdentifiersA/B(part, triangle) before
// every addContactPoint, so m_index0/m_index1 name the triangles of A (body 0) and B (body 1).
class ContactCollector final : public btManifoldResult {
 public:
  ContactCollector(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b,
                   bool through_manifold, std::vector<RawContact>& out)
      : btManifoldResult(a, b), through_manifold_(through_manifold), out_(out) {}

  void addContactPoint(const btVector3& normal_on_b, const btVector3& point,
                       btScalar distance) override {
    if (through_manifold_) {
      btManifoldResult::addContactPoint(normal_on_b, point, distance);
      return;
    }
    out_.push_back(RawContact{point, normal_on_b, distance, m_index0, m_index1});
  }

  /// With manifold=true: the points the persistent manifold kept.
  void readManifold() {
    const btPersistentManifold* manifold = getPersistentManifold();
    if (manifold == nullptr) return;
    for (int i = 0; i < manifold->getNumContacts(); ++i) {
      const btManifoldPoint& p = manifold->getContactPoint(i);
      out_.push_back(RawContact{p.getPositionWorldOnB(), p.m_normalWorldOnB, p.getDistance(),
                                p.m_index0, p.m_index1});
    }
  }

 private:
  bool through_manifold_;
  std::vector<RawContact>& out_;
};

btDefaultCollisionConstructionInfo smallPools() {
  // One manifold and one algorithm live at a time; the default pools (4096 each) would only add
  // megabytes to every instance.
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 4;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 4;
  return info;
}

btCollisionAlgorithmConstructionInfo algorithmInfo(btDispatcher* dispatcher) {
  btCollisionAlgorithmConstructionInfo info;
  info.m_dispatcher1 = dispatcher;
  return info;
}

class BulletBackend final : public Backend {
 public:
  explicit BulletBackend(const Settings& settings)
      : settings_(settings),
        configuration_(smallPools()),
        dispatcher_(&configuration_),
        // Made once and reused: processCollision() starts with clearCache(), which releases the
        // previous query's manifold. No dispatcher lookup is involved, so GImpact needs no
        // registration here (README.md: what contactPairTest needs instead).
        algorithm_(algorithmInfo(&dispatcher_), nullptr, nullptr) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs | QueryKind::kContacts;
    caps.update = true;
    caps.counts_update_work = true;
    caps.max_contacts = settings_.manifold ? MANIFOLD_CACHE_SIZE : 0;
    caps.notes =
        "GImpact (btGImpactMeshShape, quantized AABB trees, clipping triangle test). No early "
        "exit: boolean queries compute all contacts. Pairs are the triangle pairs GImpact reports "
        "contacts for: it also reports pairs that only lie behind each other's planes (not "
        "intersecting), and pairs closer than the sum of the margins. Tree boxes are quantized to "
        "16 bits with rounding to nearest, not outwards. Contact positions lie on A or on B; "
        "depths include the margins. No work counters.";
    if (settings_.manifold) {
      caps.notes +=
          " manifold=true: contacts pass through a persistent manifold, which keeps at most 4 "
          "points (and pairs).";
    }
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& /*needs*/,
                                              const StateSibling& /*sibling*/) override {
    // Every query kind uses the same shape, and GImpact reads triangles from the arrays the model
    // keeps anyway, so the needs change nothing.
    return std::unique_ptr<BackendModel>(std::make_unique<BulletModel>(mesh, settings_));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override {
    counters = static_cast<BulletModel&>(model).update(positions);
    return {};
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    btGImpactMeshShape* shape_a = static_cast<BulletModel&>(a).shape();
    btGImpactMeshShape* shape_b = static_cast<BulletModel&>(b).shape();
    // Two collision objects of the instance, not of the models, so that a model may meet itself.
    if (settings_.relative_pose) {
      object_a_.getWorldTransform().setIdentity();
      object_b_.setWorldTransform(toBullet(pose_a.inverse() * pose_b));
    } else {
      object_a_.setWorldTransform(toBullet(pose_a));
      object_b_.setWorldTransform(toBullet(pose_b));
    }
    object_a_.setCollisionShape(shape_a);
    object_b_.setCollisionShape(shape_b);
    const btCollisionObjectWrapper wrap_a(nullptr, shape_a, &object_a_,
                                          object_a_.getWorldTransform(), -1, -1);
    const btCollisionObjectWrapper wrap_b(nullptr, shape_b, &object_b_,
                                          object_b_.getWorldTransform(), -1, -1);
    raw_.clear();
    ContactCollector collector(&wrap_a, &wrap_b, settings_.manifold, raw_);
    algorithm_.processCollision(&wrap_a, &wrap_b, dispatch_info_, &collector);
    if (settings_.manifold) collector.readManifold();

    result.intersecting = !raw_.empty();
    switch (request.kind) {
      case QueryKind::kBoolean:
        break;
      case QueryKind::kAllPairs:
        collectPairs(request.max_pairs, result);
        break;
      case QueryKind::kContacts:
        collectContacts(pose_a, request.max_contacts, result);
        break;
      default:  // not offered (GImpact has no mesh-mesh distance): the host refuses it first
        return {StatusCode::kUnsupported,
                std::string("bullet: does not answer ") + queryKindName(request.kind) + " queries"};
    }
    return {};
  }

 private:
  // GImpact reports a triangle pair once per contact point (up to 16 clipped points), so the
  // pairs are sorted and made unique.
  void collectPairs(std::uint64_t max_pairs, QueryResult& result) {
    std::vector<TrianglePair>& pairs = result.pairs;
    pairs.resize(raw_.size());
    for (std::size_t i = 0; i < raw_.size(); ++i) {
      pairs[i] = TrianglePair{raw_[i].triangle_a, raw_[i].triangle_b};
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    if (max_pairs != 0 && pairs.size() > max_pairs) {
      pairs.resize(static_cast<std::size_t>(max_pairs));
      result.truncated = true;
    }
  }

  // Bullet's normal points from B towards A; ours from A towards B. Points and normals come back
  // from A's frame when the query ran there.
  void collectContacts(const Pose& pose_a, std::uint64_t max_contacts, QueryResult& result) {
    std::size_t count = raw_.size();
    if (max_contacts != 0 && count > max_contacts) {
      count = static_cast<std::size_t>(max_contacts);
      result.truncated = true;
    }
    result.contacts.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const RawContact& raw = raw_[i];
      Contact& c = result.contacts[i];
      c.position = toEigen(raw.point);
      c.normal = -toEigen(raw.normal_on_b).normalized();
      if (settings_.relative_pose) {
        c.position = pose_a * c.position;
        c.normal = pose_a.linear() * c.normal;
      }
      c.depth = std::max(0.0, -static_cast<double>(raw.distance));
      c.triangle_a = raw.triangle_a;
      c.triangle_b = raw.triangle_b;
    }
  }

  Settings settings_;
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDispatcherInfo dispatch_info_;
  btCollisionObject object_a_;
  btCollisionObject object_b_;
  btGImpactCollisionAlgorithm algorithm_;  // after the dispatcher: released before it
  std::vector<RawContact> raw_;
};

Result<std::unique_ptr<Backend>> create(const std::string& /*variant*/, BackendOptions& options) {
  Settings settings;
  const bool margin_given = options.has("margin");
  Result<double> margin = options.getDouble("margin", 0.0, 0.0, 1e9);
  if (!margin.ok()) return margin.status();
  Result<bool> engine_margin = options.getBool("engine_margin", false);
  if (!engine_margin.ok()) return engine_margin.status();
  Result<bool> relative_pose = options.getBool("relative_pose", true);
  if (!relative_pose.ok()) return relative_pose.status();
  Result<bool> manifold = options.getBool("manifold", false);
  if (!manifold.ok()) return manifold.status();
  if (engine_margin.value() && margin_given) {
    return Status(StatusCode::kInvalidArgument,
                  "options margin and engine_margin=true exclude each other");
  }
  settings.margin = margin.value();
  settings.engine_margin = engine_margin.value();
  settings.relative_pose = relative_pose.value();
  settings.manifold = manifold.value();
  return std::unique_ptr<Backend>(std::make_unique<BulletBackend>(settings));
}

const PluginInfo& describe() {
  static const PluginInfo info{
      COLLIDO_BULLET_PLUGIN_NAME,
      kVersion,
      "Bullet GImpact",
      std::string(COLLIDO_BULLET_PACKAGE_VERSION) + " (Debian libbullet, headers " +
          std::to_string(btGetVersion()) + ", " +
          (btIsDoublePrecision() != 0 ? "double" : "single") + " precision)",
      {{COLLIDO_BULLET_VARIANT,
        std::string("Bullet GImpact mesh-mesh (btGImpactMeshShape), ") +
            (btIsDoublePrecision() != 0 ? "double" : "single") +
            " precision; options margin (0), engine_margin, relative_pose (true), manifold "
            "(false)"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::bullet

// COLLIDO_DEFINE_PLUGIN pastes its id with ##, which would not expand the macro; one level of
// indirection lets COLLIDO_BULLET_PLUGIN_ID (bullet or bullet_double) expand first.
#define COLLIDO_BULLET_DEFINE_PLUGIN(id, describe) COLLIDO_DEFINE_PLUGIN(id, describe)
COLLIDO_BULLET_DEFINE_PLUGIN(COLLIDO_BULLET_PLUGIN_ID, collido::bullet::describe)
