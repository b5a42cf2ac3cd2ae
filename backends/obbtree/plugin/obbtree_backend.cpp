// The OBB tree as a Collidoscope plugin: a thin adapter from the narrow interface to lib/.
#include <memory>

#include <collido/obbtree/collide.h>
#include <collido/obbtree/contacts.h>
#include <collido/obbtree/distance.h>
#include <collido/obbtree/first_contact.h>
#include <collido/obbtree/tree.h>
#include <collido/plugin_export.h>

namespace collido::obbtree {
namespace {

constexpr const char* kVersion = "0.1.0";

class ObbTreeModel final : public BackendModel {
 public:
  // A model that will answer contacts keeps where each input triangle sits in leaf order
  // (4 bytes a triangle); others pay nothing for contacts.
  ObbTreeModel(ObbTree tree, bool contacts)
      : tree_(std::move(tree)), radius_(radiusAboutOrigin(tree_)) {
    if (contacts) positions_ = leafPositionsOfIds(tree_);
  }
  std::size_t memoryBytes() const override {
    return sizeof(*this) + tree_.memoryBytes() + positions_.capacity() * sizeof(std::int32_t);
  }
  const ObbTree& tree() const { return tree_; }
  // The vertices' largest distance from the origin, a motion's reach, kept with the vertices.
  double radius() const { return radius_; }
  RefitReport refit(const Eigen::Ref<const Eigen::Matrix3Xd>& positions) {
    const RefitReport report = tree_.refit(positions);
    radius_ = radiusAboutOrigin(tree_);
    return report;
  }
  // The adapter asks contacts only of models whose needs announced them.
  const std::vector<std::int32_t>& leafPositions() const { return positions_; }

 private:
  ObbTree tree_;
  double radius_ = 0.0;
  std::vector<std::int32_t> positions_;
};

class ObbTreeBackend final : public Backend {
 public:
  ObbTreeBackend(BuildOptions options, int threads, bool share_states, bool vector_box_tests,
                 double contact_merge_radius)
      : options_(options),
        threads_(threads),
        share_states_(share_states),
        vector_box_tests_(vector_box_tests),
        contact_merge_radius_(contact_merge_radius) {}

  Capabilities capabilities() const override {
    Capabilities caps;
    caps.shape_kinds = static_cast<std::uint32_t>(ShapeKind::kTriangleMesh);
    caps.queries = QueryKindSet(QueryKind::kBoolean) | QueryKind::kAllPairs | QueryKind::kContacts |
                   QueryKind::kDistance | QueryKind::kFirstContact;
    caps.update = true;
    caps.counts_bv_tests = true;
    caps.counts_primitive_tests = true;
    caps.counts_update_work = true;
    caps.notes =
        "Exact triangle-pair answers (exact predicates on the doubles of B's triangles mapped "
        "into A's frame). Distances by best-first descent with box-pair lower bounds, with a "
        "certified interval about 1e-13 of the coordinates' magnitude wide (at most 2^-19 of the "
        "distance beyond the request's tolerance): pairs the double computation cannot certify "
        "are decided exactly, and 0 means the exact test found contact. Contacts as "
        "docs/DESIGN.md defines them: one per exact intersecting pair at the mean of its "
        "intersection set (double precision where well conditioned, else exact), the face "
        "normal with the smaller local depth; merged within contact_merge_radius, capped by "
        "max_contacts keeping a spread of them. First contact over a step by conservative "
        "advancement on the certified distance, closed by exact collision tests: certified as "
        "the exact reference's bracket is.";
    return caps;
  }

  Result<std::unique_ptr<BackendModel>> build(const MeshView& mesh, const BuildNeeds& needs,
                                              const StateSibling& sibling) override {
    // Boolean and all-pairs queries use the same tree; a model that will deform keeps the
    // vertex lists of a fast refit. Another state of the same object shares the sibling's
    // leaf order (share_states).
    BuildOptions options = options_;
    options.deformable = needs.deforms;
    const bool contacts = needs.queries.contains(QueryKind::kContacts);
    if (share_states_ && sibling.model != nullptr) {
      const ObbTree& like = static_cast<const ObbTreeModel&>(*sibling.model).tree();
      return std::unique_ptr<BackendModel>(std::make_unique<ObbTreeModel>(
          ObbTree::buildLike(like, mesh.vertices, options), contacts));
    }
    return std::unique_ptr<BackendModel>(std::make_unique<ObbTreeModel>(
        ObbTree::build(mesh.vertices, mesh.triangles, options), contacts));
  }

  Status update(BackendModel& model, const Eigen::Ref<const Eigen::Matrix3Xd>& positions,
                UpdateCounters& counters) override {
    const RefitReport report = static_cast<ObbTreeModel&>(model).refit(positions);
    counters.nodes_refit = report.nodes_refit;
    counters.rebuilds = report.subtrees_rebuilt;
    counters.nodes_rebuilt = report.nodes_rebuilt;
    counters.counted = true;
    return {};
  }

  Status query(BackendModel& a, const Pose& pose_a, BackendModel& b, const Pose& pose_b,
               const QueryRequest& request, QueryResult& result) override {
    const ObbTreeModel& model_a = static_cast<ObbTreeModel&>(a);
    const ObbTreeModel& model_b = static_cast<ObbTreeModel&>(b);
    const ObbTree& tree_a = model_a.tree();
    const ObbTree& tree_b = model_b.tree();
    if (request.kind == QueryKind::kFirstContact) {
      return firstContactQuery(model_a, pose_a, model_b, pose_b, request, result);
    }
    if (request.kind == QueryKind::kDistance) {
      DistanceAnswer answer;
      distance(tree_a, pose_a, tree_b, pose_b,
               DistanceRequest{request.abs_tolerance, request.rel_tolerance}, answer);
      DistanceResult& d = result.distance;
      d.distance = answer.distance;
      d.point_a = answer.point_a;
      d.point_b = answer.point_b;
      d.triangle_a = answer.triangle_a;
      d.triangle_b = answer.triangle_b;
      d.lower = answer.lower_bound;
      d.upper = answer.upper_bound;
      result.intersecting = answer.distance == 0.0;
      result.counters.bv_tests = answer.box_tests;
      result.counters.primitive_tests = answer.triangle_tests;
      result.counters.counts_bv_tests = true;
      result.counters.counts_primitive_tests = true;
      return {};
    }
    CollideRequest collide_request;
    collide_request.mode =
        request.kind == QueryKind::kBoolean ? CollideMode::kFirstHit : CollideMode::kAllPairs;
    // Contacts need every pair: the cap applies to the merged manifold, not to the search.
    collide_request.max_pairs = request.kind == QueryKind::kAllPairs ? request.max_pairs : 0;
    collide_request.threads = threads_;
    collide_request.vector_box_tests = vector_box_tests_;
    collide(tree_a, pose_a, tree_b, pose_b, collide_request, scratch_);
    result.intersecting = !scratch_.pairs.empty();
    result.truncated = scratch_.truncated;
    if (request.kind == QueryKind::kContacts) {
      contactsOfPairs(tree_a, model_a.leafPositions(), pose_a, tree_b, model_b.leafPositions(),
                      pose_b, scratch_.pairs,
                      ContactOptions{contact_merge_radius_, request.max_contacts}, contacts_);
      result.truncated = contacts_.truncated;
      result.contacts.resize(contacts_.contacts.size());
      for (std::size_t i = 0; i < contacts_.contacts.size(); ++i) {
        const TriangleContact& c = contacts_.contacts[i];
        result.contacts[i] = Contact{c.position, c.normal, c.depth, c.triangle_a, c.triangle_b};
      }
      scratch_.pairs.clear();
    }
    result.pairs.resize(scratch_.pairs.size());
    for (std::size_t i = 0; i < scratch_.pairs.size(); ++i) {
      result.pairs[i] = collido::TrianglePair{scratch_.pairs[i].a, scratch_.pairs[i].b};
    }
    result.counters.bv_tests = scratch_.box_tests;
    result.counters.primitive_tests = scratch_.triangle_tests;
    result.counters.counts_bv_tests = true;
    result.counters.counts_primitive_tests = true;
    return {};
  }

 private:
  static Status firstContactQuery(const ObbTreeModel& a, const Pose& pose_a, const ObbTreeModel& b,
                                  const Pose& pose_b, const QueryRequest& request,
                                  QueryResult& result) {
    // The adapter has checked every pose is rigid.
    const StepMotion motion_a = StepMotion::between(pose_a, request.step->pose_a, "A").value();
    const StepMotion motion_b = StepMotion::between(pose_b, request.step->pose_b, "B").value();
    FirstContactAnswer answer;
    firstContact(MovingTree{a.tree(), motion_a, a.radius()},
                 MovingTree{b.tree(), motion_b, b.radius()}, request.step->bracket_width, answer);
    result.first_contact = {answer.touches, answer.t_lo, answer.t_hi, answer.triangle_a,
                            answer.triangle_b};
    result.intersecting = answer.touches;
    result.counters.bv_tests = answer.box_tests;
    result.counters.primitive_tests = answer.triangle_tests;
    result.counters.counts_bv_tests = true;
    result.counters.counts_primitive_tests = true;
    return {};
  }

  BuildOptions options_;
  int threads_ = 1;
  bool share_states_ = true;
  bool vector_box_tests_ = true;
  double contact_merge_radius_ = 0.0;
  CollideResult scratch_;
  ContactAnswer contacts_;
};

Result<std::unique_ptr<Backend>> create(const std::string& /*variant*/, BackendOptions& options) {
  Result<std::int64_t> leaf =
      options.getInt("max_leaf_triangles", 1, 1, obbtree::kMaxLeafTriangles);
  if (!leaf.ok()) return leaf.status();
  Result<bool> float_boxes = options.getBool("float_boxes", false);
  if (!float_boxes.ok()) return float_boxes.status();
  Result<bool> split_by_cost = options.getBool("split_by_cost", true);
  if (!split_by_cost.ok()) return split_by_cost.status();
  Result<std::int64_t> threads = options.getInt("threads", 1, 1, 256);
  if (!threads.ok()) return threads.status();
  Result<double> rebuild_ratio = options.getDouble("rebuild_ratio", 0.0, 0.0, 1e6);
  if (!rebuild_ratio.ok()) return rebuild_ratio.status();
  if (rebuild_ratio.value() > 0.0 && rebuild_ratio.value() < 1.0) {
    return Status(StatusCode::kInvalidArgument,
                  "obbtree: rebuild_ratio must be 0 (never) or at least 1");
  }
  Result<bool> share_states = options.getBool("share_states", true);
  if (!share_states.ok()) return share_states.status();
  Result<bool> vector_box_tests = options.getBool("vector_box_tests", true);
  if (!vector_box_tests.ok()) return vector_box_tests.status();
  Result<double> merge_radius = options.getDouble("contact_merge_radius", 0.0, 0.0, 1e300);
  if (!merge_radius.ok()) return merge_radius.status();
  BuildOptions build_options;
  build_options.max_leaf_triangles = static_cast<std::int32_t>(leaf.value());
  build_options.float_boxes = float_boxes.value();
  build_options.split_by_cost = split_by_cost.value();
  build_options.rebuild_ratio = rebuild_ratio.value();
  return std::unique_ptr<Backend>(std::make_unique<ObbTreeBackend>(
      build_options, static_cast<int>(threads.value()), share_states.value(),
      vector_box_tests.value(), merge_radius.value()));
}

const PluginInfo& describe() {
  static const PluginInfo info{
      "obbtree",
      kVersion,
      "Collidoscope OBB tree",
      kVersion,
      {{"obbtree",
        "OBB tree (covariance-fitted boxes, cost-driven splits, 15-axis SAT, exact triangle "
        "tests); "
        "options max_leaf_triangles (default 1), float_boxes (default false: boxes in double), "
        "split_by_cost (default true: each node split where a cost model of the tests below it "
        "prefers; false: at the mean of the triangle centres, the dissertation's rule), "
        "threads (default 1: all-pairs queries on this many threads), rebuild_ratio (default "
        "0: a deforming model's subtree is rebuilt when its box grew past this many times its "
        "fresh volume; 0 never), share_states (default true: the trees of an object's active "
        "states "
        "with one triangle list share its leaf order, each box fitted fresh per state), "
        "vector_box_tests (default true: a node's grandchildren tested against the other node "
        "four at a time in AVX2 where the CPU has it; false: one at a time in scalar code), "
        "contact_merge_radius (default 0: contacts closer than this merge into the deepest; 0 "
        "merges coincident ones only)"}},
      &create};
  return info;
}

}  // namespace
}  // namespace collido::obbtree

COLLIDO_DEFINE_PLUGIN(obbtree, collido::obbtree::describe)
