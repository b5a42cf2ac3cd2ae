// FCL as a Collidoscope plugin: fcl::BVHModel with one box type per variant, queried through
// FCL's public fcl::collide() — the path FCL's users take, so its costs are theirs (for the
// non-oriented AABB type that includes FCL copying and re-fitting both models into the world
// frame on every query).
//
// Question to FCL request:
//   boolean   -> num_max_contacts = 1, enable_contact = false (FCL stops at the first pair);
//   all_pairs -> num_max_contacts = limit + 1 (or unlimited), enable_contact = false: FCL records
//                one contact per intersecting triangle pair, with the triangle ids b1, b2 and no
//                contact geometry, which is all the question needs;
//   contacts  -> enable_contact = true: FCL's per-triangle-pair contact points, normal (o1 to o2)
//                and penetration depth;
//   distance  -> fcl::distance() with enable_nearest_points and the request's tolerances as
//                FCL's abs_err / rel_err; offered for the box types whose mesh-mesh distance FCL
//                implements (RSS, OBBRSS, kIOS). Its nearest points are in the world frame
//                (FCL >= 0.6).
#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fcl/fcl.h>

#include <collido/plugin_export.h>

namespace collido::fcl_backend {
namespace {

using Transform = fcl::Transform3d;

/// The model of one mesh, in the box type of the variant.
class FclModel : public BackendModel {
 public:
  virtual const fcl::CollisionGeometryd& geometry() const = 0;
  /// Moves the vertices; says what FCL rebuilt or refit (its whole tree, either way).
  virtual UpdateCounters update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) = 0;
};

template <typename BV>
class TypedModel final : public FclModel {
 public:
  TypedModel(const MeshView& mesh, bool rebuild_on_update) : rebuild_on_update_(rebuild_on_update) {
    std::vector<fcl::Vector3d> points(static_cast<std::size_t>(mesh.vertices.cols()));
    for (std::size_t i = 0; i < points.size(); ++i) {
      points[i] = mesh.vertices.col(static_cast<Eigen::Index>(i));
    }
    triangles_.resize(static_cast<std::size_t>(mesh.triangles.cols()));
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const auto c = mesh.triangles.col(static_cast<Eigen::Index>(t));
      triangles_[t] = fcl::Triangle(static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]),
                                    static_cast<std::size_t>(c[2]));
    }
    buildFrom(points);
    // The triangles are kept only to rebuild from; a refit reuses FCL's own copy.
    if (!rebuild_on_update_) std::vector<fcl::Triangle>().swap(triangles_);
  }

  const fcl::CollisionGeometryd& geometry() const override { return *model_; }

  UpdateCounters update(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) override {
    // All vertices at once through updateSubModel: FCL's update buffer is not initialised while
    // updating, so a partial update would leave garbage in it.
    std::vector<fcl::Vector3d> points(static_cast<std::size_t>(positions.cols()));
    for (std::size_t i = 0; i < points.size(); ++i) {
      points[i] = positions.col(static_cast<Eigen::Index>(i));
    }
    UpdateCounters counters;
    counters.counted = true;
    if (rebuild_on_update_) {
      buildFrom(points);
      counters.rebuilds = 1;
      counters.nodes_rebuilt = static_cast<std::uint64_t>(model_->getNumBVs());
      return counters;
    }
    check(model_->beginUpdateModel(), "beginUpdateModel");
    check(model_->updateSubModel(points), "updateSubModel");
    check(model_->endUpdateModel(/*refit=*/true, /*bottomup=*/true), "endUpdateModel");
    model_->computeLocalAABB();
    counters.nodes_refit = static_cast<std::uint64_t>(model_->getNumBVs());
    return counters;
  }

  std::size_t memoryBytes() const override {
    // Counted here: BVHModel::memUsage() in FCL 0.7 returns BVH_OK (0) instead of its total.
    // Nodes, triangles with their primitive indices, vertices (twice once a model has been
    // updated: FCL keeps the previous positions), and the model object.
    const auto& m = *model_;
    const std::size_t vertex_copies = m.prev_vertices != nullptr ? 2 : 1;
    return static_cast<std::size_t>(m.getNumBVs()) * sizeof(fcl::BVNode<BV>) +
           static_cast<std::size_t>(m.num_tris) * (sizeof(fcl::Triangle) + sizeof(unsigned)) +
           static_cast<std::size_t>(m.num_vertices) * sizeof(fcl::Vector3d) * vertex_copies +
           sizeof(fcl::BVHModel<BV>);
  }

 private:
  static void check(int code, const char* step) {
    if (code != fcl::BVH_OK) {
      throw std::runtime_error(std::string("FCL ") + step + " returned " + std::to_string(code));
    }
  }

  // A new tree over `points` and the kept triangles (at build, and for every rebuild).
  void buildFrom(const std::vector<fcl::Vector3d>& points) {
    auto model = std::make_shared<fcl::BVHModel<BV>>();
    check(model->beginModel(static_cast<int>(triangles_.size()), static_cast<int>(points.size())),
          "beginModel");
    check(model->addSubModel(points, triangles_), "addSubModel");
    check(model->endModel(), "endModel");
    model->computeLocalAABB();
    model_ = std::move(model);
  }

  bool rebuild_on_update_ = false;
  std::vector<fcl::Triangle> triangles_;
  std::shared_ptr<fcl::BVHModel<BV>> model_;
};

enum class BoxType { kObb, kObbRss, kKios, kRss, kAabb };

std::unique_ptr<FclModel> makeModel(BoxType type, const MeshView& mesh, bool rebuild) {
  switch (type) {
    case BoxType::kObb:
      return std::make_unique<TypedModel<fcl::OBBd>>(mesh, rebuild);
    case BoxType::kObbRss:
      return std::make_unique<TypedModel<fcl::OBBRSSd>>(mesh, rebuild);
    case BoxType::kKios:
      return std::make_unique<TypedModel<fcl::kIOSd>>(mesh, rebuild);
    case BoxType::kRss:
      return std::make_unique<TypedModel<fcl::RSSd>>(mesh, rebuild);
    case BoxType::kAabb:
      return std::make_unique<TypedModel<fcl::AABBd>>(mesh, rebuild);
  }
  return nullptr;
}

Transform toTransform(const Pose& pose) {
  Transform tf = Transform::Identity();
  tf.linear() = pose.linear();
  tf.translation() = pose.translation();
  return tf;
}

class FclBackend final : public Backend {
 public:
  FclBackend(BoxType type, bool rebuild) : type_(type), rebuild_(rebuild) {}

  // OBBRSS keeps an OBB for collision and an RSS for distance in every node. Where the objects
  // linked to this one are asked only one of those, the half they never use is not built; the
  // whole linked set gets the same type, since FCL collides and measures only equal types.
  // First contact measures: FCL's conservative advancement runs a distance traversal.
  BoxType typeFor(const BuildNeeds& needs) const {
    if (type_ != BoxType::kObbRss || needs.linked_queries.empty()) return type_;
    const std::uint32_t distance = static_cast<std::uint32_t>(QueryKind::kDistance) |
                                   static_cast<std::uint32_t>(QueryKind::kFirstContact);
    const bool measures = (needs.linked_queries.bits() & distance) != 0;
    const bool collides = (needs.linked_queries.bits() & ~distance) != 0;
    if (measures && collides) return BoxType::kObbRss;
    return measures ? BoxType::kRss : BoxType::kObb;
  }

  // FCL's mesh-mesh distance traversal exists for these box types only.
  bool answersDistance() const {
    return type_ == BoxType::kRss || type_ == BoxType::kObbRss || type_ == BoxType::kKios;
  }

  // FCL's conservative advancement has a mesh-mesh entry for AABB, OBB, RSS and OBBRSS; on OBB
  // it prints "OBB distance not implemented!" for every node pair, so it is not offered there.
  bool answersFirstContact() const {
    return type_ == BoxType::kRss || type_ == BoxType::kObbRss || type_ == BoxType::kAabb;
  }

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs | QueryKind::kContacts;
    if (answersDistance()) caps.queries |= QueryKind::kDistance;
    if (answersFirstContact()) caps.queries |= QueryKind::kFirstContact;
    caps.update = true;
    caps.counts_update_work = true;
    caps.notes =
        "fcl::collide() on BVHModel meshes; triangle pairs decided by FCL's floating-point "
        "triangle test; contacts are FCL's per-pair points, normal (A to B) and depth. No work "
        "counters: the public API does not expose them. First contact by "
        "fcl::continuousCollide (conservative advancement, linear interpolated motion) as it "
        "is: one time of contact, reported as a bracket of width 0 (README).";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                              const StateSibling& /*sibling*/) override {
    return std::unique_ptr<BackendModel>(makeModel(typeFor(needs), mesh, rebuild_));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override {
    counters = static_cast<FclModel&>(model).update(positions);
    return {};
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    // FCL answers a pair of unequal box types with a warning and no collision, a wrong answer.
    const fcl::NODE_TYPE type_a = static_cast<FclModel&>(a).geometry().getNodeType();
    const fcl::NODE_TYPE type_b = static_cast<FclModel&>(b).geometry().getNodeType();
    if (type_a != type_b) {
      return {StatusCode::kInvalidArgument,
              "fcl: the two models have different box types (FCL node types " +
                  std::to_string(type_a) + " and " + std::to_string(type_b) +
                  "); build both with the same linked query kinds"};
    }
    if (request.kind == QueryKind::kFirstContact) {
      return firstContact(static_cast<FclModel&>(a), pose_a, static_cast<FclModel&>(b), pose_b,
                          request, result);
    }
    if (request.kind == QueryKind::kDistance) {
      return distance(static_cast<FclModel&>(a), pose_a, static_cast<FclModel&>(b), pose_b, request,
                      result);
    }
    const std::size_t unlimited = std::numeric_limits<std::size_t>::max();
    fcl::CollisionRequestd fcl_request;
    std::uint64_t limit = 0;
    switch (request.kind) {
      case QueryKind::kBoolean:
        fcl_request.num_max_contacts = 1;
        fcl_request.enable_contact = false;
        break;
      case QueryKind::kAllPairs:
        limit = request.max_pairs;
        fcl_request.num_max_contacts = limit == 0 ? unlimited : limit + 1;
        fcl_request.enable_contact = false;
        break;
      case QueryKind::kContacts:
        limit = request.max_contacts;
        fcl_request.num_max_contacts = limit == 0 ? unlimited : limit + 1;
        fcl_request.enable_contact = true;
        break;
      default:  // distance is answered above; the host refuses kinds not offered
        break;
    }
    fcl_result_.clear();
    fcl::collide(&static_cast<FclModel&>(a).geometry(), toTransform(pose_a),
                 &static_cast<FclModel&>(b).geometry(), toTransform(pose_b), fcl_request,
                 fcl_result_);
    fcl_result_.getContacts(contacts_);
    result.intersecting = fcl_result_.isCollision();
    // One more than the limit was asked for, so a limit that bit is told from one that fits.
    if (limit != 0 && contacts_.size() > limit) {
      contacts_.resize(limit);
      result.truncated = true;
    }
    if (request.kind == QueryKind::kContacts) {
      result.contacts.reserve(contacts_.size());
      for (const fcl::Contactd& c : contacts_) {
        Contact contact;
        contact.position = c.pos;
        contact.normal = c.normal;
        contact.depth = c.penetration_depth;
        contact.triangle_a = static_cast<std::int32_t>(c.b1);
        contact.triangle_b = static_cast<std::int32_t>(c.b2);
        result.contacts.push_back(contact);
      }
      return {};
    }
    result.pairs.reserve(contacts_.size());
    for (const fcl::Contactd& c : contacts_) {
      result.pairs.push_back(
          TrianglePair{static_cast<std::int32_t>(c.b1), static_cast<std::int32_t>(c.b2)});
    }
    return {};
  }

 private:
  // FCL's continuousCollide as it is: conservative advancement (CCDC_CONSERVATIVE_ADVANCEMENT)
  // on FCL's interpolated motion with its reference point at the origin (the interface's
  // StepMotion). The motions are made here with the constructor that takes rotations and
  // translations: it is the only one that sets the reference point and then the velocities (the
  // overload taking two transforms per object leaves its reference point unset, and the one
  // taking two transforms and a point its velocities, uninitialised memory that made FCL's
  // answers depend on what the process did before; README). FCL gives one time; it is reported as
  // both ends of the bracket.
  static fcl::InterpMotion<double> motionBetween(const Pose& start, const Pose& end) {
    return fcl::InterpMotion<double>(start.linear(), start.translation(), end.linear(),
                                     end.translation(), fcl::Vector3d::Zero());
  }

  static Status firstContact(const FclModel& a, const Pose& pose_a, const FclModel& b,
                             const Pose& pose_b, const QueryRequest& request, QueryResult& result) {
    fcl::ContinuousCollisionRequestd fcl_request;
    fcl_request.ccd_motion_type = fcl::CCDM_LINEAR;
    fcl_request.ccd_solver_type = fcl::CCDC_CONSERVATIVE_ADVANCEMENT;
    fcl::ContinuousCollisionResultd fcl_result;
    const fcl::InterpMotion<double> motion_a = motionBetween(pose_a, request.step->pose_a);
    const fcl::InterpMotion<double> motion_b = motionBetween(pose_b, request.step->pose_b);
    const double toc = fcl::continuousCollide(&a.geometry(), &motion_a, &b.geometry(), &motion_b,
                                              fcl_request, fcl_result);
    if (toc < 0.0) return {StatusCode::kInternal, "fcl: continuousCollide refused the pair"};
    FirstContactResult& c = result.first_contact;
    c.touches = fcl_result.is_collide;
    c.t_lo = c.t_hi =
        fcl_result.is_collide ? std::clamp(fcl_result.time_of_contact, 0.0, 1.0) : 1.0;
    result.intersecting = c.touches;
    return {};
  }

  Status distance(const FclModel& a, const Pose& pose_a, const FclModel& b, const Pose& pose_b,
                  const QueryRequest& request, QueryResult& result) const {
    fcl::DistanceRequestd fcl_request(/*enable_nearest_points=*/true);
    fcl_request.abs_err = request.abs_tolerance;
    fcl_request.rel_err = request.rel_tolerance;
    fcl::DistanceResultd fcl_result;
    fcl::distance(&a.geometry(), toTransform(pose_a), &b.geometry(), toTransform(pose_b),
                  fcl_request, fcl_result);
    DistanceResult& d = result.distance;
    // FCL answers a negative distance for some colliding shapes; the interface's is >= 0.
    d.distance = std::max(fcl_result.min_distance, 0.0);
    d.point_a = fcl_result.nearest_points[0];
    d.point_b = fcl_result.nearest_points[1];
    d.triangle_a = static_cast<std::int32_t>(fcl_result.b1);
    d.triangle_b = static_cast<std::int32_t>(fcl_result.b2);
    result.intersecting = d.distance == 0.0;
    return {};
  }

  BoxType type_;
  bool rebuild_ = false;
  fcl::CollisionResultd fcl_result_;
  std::vector<fcl::Contactd> contacts_;
};

struct VariantSpec {
  const char* name;
  BoxType type;
};

constexpr VariantSpec kVariants[] = {{"fcl:obb", BoxType::kObb},
                                     {"fcl:obbrss", BoxType::kObbRss},
                                     {"fcl:kios", BoxType::kKios},
                                     {"fcl:rss", BoxType::kRss},
                                     {"fcl:aabb", BoxType::kAabb}};

Result<std::unique_ptr<Backend>> create(const std::string& variant, BackendOptions& options) {
  // rebuild=true: update() builds a new tree over the moved vertices instead of FCL's refit
  // (beginUpdateModel / updateSubModel / endUpdateModel, bottom-up).
  const Result<bool> rebuild = options.getBool("rebuild", false);
  if (!rebuild.ok()) return rebuild.status();
  for (const VariantSpec& v : kVariants) {
    if (variant == v.name)
      return std::unique_ptr<Backend>(std::make_unique<FclBackend>(v.type, rebuild.value()));
  }
  return Status(StatusCode::kInvalidArgument, "fcl has no variant '" + variant + "'");
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "fcl",
      "0.1.0",
      "FCL",
      COLLIDO_FCL_VERSION,
      {{"fcl:obb", "FCL BVHModel<OBB> (oriented boxes, as RAPID)"},
       {"fcl:obbrss", "FCL BVHModel<OBBRSS> (OBB and rectangle swept sphere per node)"},
       {"fcl:kios", "FCL BVHModel<kIOS> (k intersecting spheres, with an OBB)"},
       {"fcl:rss", "FCL BVHModel<RSS> (rectangle swept spheres)"},
       {"fcl:aabb", "FCL BVHModel<AABB> (axis-aligned boxes; models re-fitted per query)"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::fcl_backend

COLLIDO_DEFINE_PLUGIN(fcl, collido::fcl_backend::describe)
